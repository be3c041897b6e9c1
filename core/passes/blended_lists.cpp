#include "core/passes/blended_lists.h"

#include <string>

#include "core/gpuscene/scene_gpu.h"
#include "core/lightassign/compact_layout.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_bound.h"
#include "core/passes/tiled_lighting.h"
#include "core/renderer/renderer.h"
#include "include/light_assign.h"

namespace tp {

uint64_t TransparentListPlan::bytes() const {
    const uint64_t tiles = offsets.empty() ? 0 : offsets.size() - 1;
    return (tiles * TP_LA_HEADER_WORDS + capacity) * 4;
}

namespace {

// Slots of one tile's run holding `lights` lights: an index each, or (masks) a bit each.
uint32_t runSlots(uint32_t lights, bool masks) {
    return masks ? (lights + 31) / 32 : lights;
}

} // namespace

TransparentListPlan transparentListNeed(const la::TileGrid& grid, const SceneGpu& scene,
                                        bool masks, const std::vector<uint32_t>* localBound) {
    // The uploaded (camera-relative) view and lights: what the tiled pass tests.
    const gpu::FrameUniforms& f = scene.shadingFrame();
    const std::vector<gpu::LightGpu>& lights = scene.shadingLights();
    la::LightClasses classes = la::classifyLights(lights);
    std::vector<uint32_t> bound =
        localBound ? *localBound
                   : la::conservativeTileBound(grid, f.view, f.proj, lights, classes.local);
    if (masks) // candidates per tile: the directional lights + the bound (the binned run's length)
        for (uint32_t& b : bound)
            b = runSlots(uint32_t(classes.directional.size()) + b, true);
    la::CompactLayout compact =
        la::makeCompactLayout(bound, masks ? 0u : uint32_t(classes.directional.size()));
    return {std::move(compact.offsets), compact.slots, compact.slots, masks};
}

TransparentListPlan planTransparentLists(const la::TileGrid& grid, const SceneGpu& scene,
                                         uint64_t limit, const std::string& deviceName, bool masks,
                                         const std::vector<uint32_t>* localBound,
                                         const std::string& owner, bool manyViews) {
    TransparentListPlan plan = transparentListNeed(grid, scene, masks, localBound);
    if (plan.bytes() > limit || plan.slots > 0xffffffffull)
        throw RendererError(
            owner + ": the transparent light lists need " + std::to_string(plan.bytes()) +
            " bytes, more than maxStorageBufferRange (" + std::to_string(limit) + ") of " +
            deviceName + "; use a larger --tile, a lower --res or fewer lights");
    const uint64_t tiles = grid.count();
    const uint64_t most = std::min(tiles * runSlots(scene.lightCount(), masks),
                                   std::min<uint64_t>(limit / 4 - tiles * TP_LA_HEADER_WORDS,
                                                      0xffffffffull));
    plan.capacity = viewCapacity(plan.slots, kViewHeadroom * tiles, most, manyViews);
    return plan;
}

} // namespace tp
