#include "core/passes/blended_lists.h"

#include <string>

#include "core/lightassign/compact_layout.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_bound.h"
#include "core/render/renderer.h"
#include "core/render/scene_gpu.h"
#include "include/light_assign.h"

namespace tp {

uint64_t TransparentListPlan::bytes() const {
    const uint64_t tiles = offsets.empty() ? 0 : offsets.size() - 1;
    return (tiles * TP_LA_HEADER_WORDS + slots) * 4;
}

TransparentListPlan planTransparentLists(const la::TileGrid& grid, const SceneGpu& scene,
                                         uint64_t limit, const std::string& deviceName, bool masks,
                                         const std::vector<uint32_t>* localBound,
                                         const std::string& owner) {
    // The uploaded (camera-relative) view and lights: what the tiled pass tests.
    const gpu::FrameUniforms& f = scene.shadingFrame();
    const std::vector<gpu::LightGpu>& lights = scene.shadingLights();
    la::LightClasses classes = la::classifyLights(lights);
    std::vector<uint32_t> bound =
        localBound ? *localBound
                   : la::conservativeTileBound(grid, f.view, f.proj, lights, classes.local);
    if (masks) // candidates per tile: the directional lights + the bound (the binned run's length)
        for (uint32_t& b : bound)
            b = (uint32_t(classes.directional.size()) + b + 31) / 32;
    la::CompactLayout compact =
        la::makeCompactLayout(bound, masks ? 0u : uint32_t(classes.directional.size()));
    TransparentListPlan plan{std::move(compact.offsets), compact.slots, masks};
    if (plan.bytes() > limit || plan.slots > 0xffffffffull)
        throw RendererError(
            owner + ": the transparent light lists need " + std::to_string(plan.bytes()) +
            " bytes, more than maxStorageBufferRange (" + std::to_string(limit) + ") of " +
            deviceName + "; use a larger --tile, a lower --res or fewer lights");
    return plan;
}

} // namespace tp
