#pragma once
// Forward+'s settings resolved, once, against the device and the scene: which optional passes
// and shader variants this renderer runs (GPU binning, the light_spheres pass, subgroup culling
// and light loop, the blended pass and its second list), and what that leaves out for the
// report. The renderer (forwardplus_renderer.cpp) plans from these; nothing here records.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/renderer/renderer.h"
#include "forwardplus/fp_settings.h"

namespace tp {
class GpuContext;
class SceneGpu;
} // namespace tp

namespace tp::fp {

struct Resolved {
    bool gpuBinning = false;     // --light-bin resolved to gpu (binned only)
    bool spherePass = false;     // --light-spheres resolved: the light_spheres pass runs
    bool subgroupCull = false;   // --cull-by resolved: one subgroup culls a tile
    bool subgroupLoop = false;   // clustered, --light-loop subgroup, and the device runs it
    std::string subgroupMissing; // --light-loop subgroup asked for but unsupported: why
    bool blendPass = false;      // blended draws: forward_transparent and the blended bounds
    bool twoLists = false;       // a transparent list per tile beside the opaque one
    uint32_t numLists = 1;
};

// RendererError (one line) for what cannot run: --cull-by subgroup on a device without the
// subgroup operations, clustered assignment without the compact lists.
Resolved resolve(GpuContext& ctx, SceneGpu& scene, const SceneFeatures& features, const Settings& s);

// What this configuration leaves out, and why (the report's "left out" list).
void addLeftOut(RendererStats& stats, const Resolved& r, const Settings& s, SceneGpu& scene,
                const SceneFeatures& features);
// Every shaded fragment evaluates its tile's (cluster's) list and the unculled directional
// lights: the lists' mean (from the counters already in `stats`) stands for the fragment's list.
void addLightWork(RendererStats& stats, const Resolved& r, const Settings& s, size_t directionalLights);
// light_culling's light-versus-tile tests (the counter lights_tested, added before).
void addCullingWork(RendererStats& stats);

} // namespace tp::fp
