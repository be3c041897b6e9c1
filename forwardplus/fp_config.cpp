#include "forwardplus/fp_config.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/lightassign/light_bins.h"
#include "core/gpuscene/scene_gpu.h"
#include "forwardplus/forwardplus_shared.h"
#include "forwardplus/light_culling.h"

namespace tp::fp {

Resolved resolve(GpuContext& ctx, SceneGpu& scene, const SceneFeatures& features, const Settings& s) {
    Resolved r;
    const bool clustered = s.assign.clustered();
    r.gpuBinning = s.assign.binned() && la::binsOnGpu(ctx, s.assign.bin);
    // --light-spheres: the pass pays on a CPU device (lavapipe runs each candidate's
    // transform in every tile it is tested in); on a GPU the transform is cheap and the
    // buffer (16 MB at 1,000,000 lights) would take Forward+ past 100 MB there.
    r.spherePass = s.spheres == Spheres::Pass || (s.spheres == Spheres::Auto && ctx.isCpuDevice());
    // --light-loop subgroup where the device has the operations; otherwise the lane loop
    // (the same image), with a note in the report.
    if (clustered && s.loop == la::Loop::Subgroup) {
        r.subgroupMissing = la::subgroupLoopUnsupported(ctx.caps);
        r.subgroupLoop = r.subgroupMissing.empty();
    }
    // --cull-by: asked for, a subgroup per tile must be possible; auto takes it on a GPU that
    // can.
    const std::string noSubgroupCull = subgroupCullingUnsupported(ctx.caps);
    if (s.cullBy == CullBy::Subgroup && !noSubgroupCull.empty())
        throw RendererError("--cull-by subgroup: " + noSubgroupCull + " (use --cull-by invocation)");
    r.subgroupCull = s.cullBy == CullBy::Subgroup ||
                     (s.cullBy == CullBy::Auto && !ctx.isCpuDevice() && noSubgroupCull.empty());
    if (clustered && uint32_t(s.lists) != TP_FP_LAYOUT_COMPACT)
        throw RendererError("--light-assign clustered needs --light-lists compact (got '" + listsText(s.lists) +
                            "')");
    // Two lists only when something is blended (and drawn); clustered has one list per
    // tile whose span covers the blended surfaces too.
    r.blendPass = features.blended && scene.hasDraws(DrawFilter::Blend);
    r.twoLists = r.blendPass && !clustered;
    r.numLists = r.twoLists ? 2 : 1;
    return r;
}

void addLightWork(RendererStats& stats, const Resolved& r, const Settings& s, size_t directionalLights) {
    const bool clustered = s.assign.clustered();
    const double directional = double(directionalLights);
    // Fragments lie in the tiles with geometry: the list's mean over those (sky tiles' lists
    // are empty). Clustered: the mean over every cluster, an under-estimate.
    const char* opaque = clustered ? "lights_per_cluster_mean" : "lights_per_tile_mean";
    const double tiles = stats.counter("tiles"), withGeometry = tiles - stats.counter("tiles_without_geometry");
    const double opaqueShare = clustered ? 1.0 : tiles / std::max(1.0, withGeometry);
    stats.lightWork.push_back({"forward_opaque", PassLightWork::Base::Fragments,
                               stats.counter(opaque) * opaqueShare + directional, false,
                               std::string(opaque) + (clustered ? "" : " over the tiles with geometry") +
                                   " + directional lights, per fragment"});
    if (!r.blendPass) return;
    // Blended fragments lie in the tiles with blended fragments: the list's mean over those.
    const char* blended = clustered ? "lights_per_front_cluster_mean" : "transparent_lights_per_tile_mean";
    const double share =
        clustered ? 1.0 : stats.counter("tiles") / std::max(1.0, stats.counter("tiles_with_blended_fragments"));
    stats.lightWork.push_back({"forward_transparent", PassLightWork::Base::Fragments,
                               stats.counter(blended, stats.counter(opaque)) * share + directional, false,
                               std::string(blended) + (clustered ? "" : " over the tiles with blended fragments") +
                                   " + directional lights, per fragment"});
}

void addCullingWork(RendererStats& stats) {
    // Reported, not placed (no ceiling measures a test); both culling variants test the same
    // candidates.
    stats.opWork.push_back({"light_culling", PassOpWork::Kind::TileTests,
                            PassLightWork::Base::Items, 1.0, false,
                            "lights_tested: each tile with geometry tests its candidates, again "
                            "for its transparent list where it has blended fragments",
                            stats.counter("lights_tested")});
}

void addLeftOut(RendererStats& stats, const Resolved& r, const Settings& s, SceneGpu& scene,
                const SceneFeatures& features) {
    auto& out = stats.leftOut;
    const bool clustered = s.assign.clustered();
    if (!r.blendPass)
        out.push_back({"transparent light list, blended depth bounds, forward_transparent pass and their memory",
                       "the scene has no blended materials"});
    else if (clustered)
        out.push_back({"the second (transparent) light list per tile",
                       "clustered: one list spans the tile's opaque range widened to its blended "
                       "fragments' depths, and blended surfaces look up their own depth slice"});
    if (s.assign.binned() && !r.gpuBinning)
        out.push_back({"light_binning pass (GPU binning)",
                       "--light-bin " + la::lightBinKnob().text(s.assign.bin) +
                           " resolved to cpu: candidates built on the CPU per view"});
    if (!clustered) out.push_back({"depth slices and their bitmasks (cluster_masks)", "--light-assign tiled"});
    if (!r.spherePass)
        out.push_back({"light_spheres pass and its buffer (16 bytes per light)",
                       "--light-spheres " + spheresText(s.spheres) +
                           ": the culling computes each candidate's sphere itself"});
    if (!r.subgroupMissing.empty())
        out.push_back({"the subgroup light loop (--light-loop subgroup): shading uses the lane loop, the same image",
                       r.subgroupMissing});
    if (s.sampling.samples == 1)
        out.push_back({"MSAA targets (hdr_msaa, depth_msaa) and their resolve", "MSAA is 1x"});
    if (!scene.hasDraws(DrawFilter::Mask))
        out.push_back({"alpha-masked prepass and shading pipelines", "the scene has no masked materials"});
    if (!features.spotLights)
        out.push_back({"spot-light shading code (TP_SPEC_HAS_SPOT = 0)", "the scene has no spot lights"});
    if (uint32_t(s.lists) != TP_FP_LAYOUT_LINKED)
        out.push_back({"node counter and its reset pass", "only the 'linked' layout allocates nodes"});
    if (s.hdr == HdrStorage::Fp16)
        out.push_back({"fp32 colour storage",
                       "--hdr " + std::string(hdrText(s.hdr)) +
                           ": hdr and hdr_msaa are RGBA16F (half the bytes of RGBA32F; each rounding "
                           "below one ulp, <= 2^-10 relative; values saturate at 65504)"});
}

} // namespace tp::fp
