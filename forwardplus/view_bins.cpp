#include "forwardplus/view_bins.h"

#include <algorithm>

#include "core/gpuscene/scene_gpu.h"
#include "core/lightassign/light_bins.h"
#include "core/passes/light_binning.h"

namespace tp::fp {

ViewBins binView(const SceneGpu& scene, const ViewBinning& b) {
    const gpu::FrameUniforms& f = scene.shadingFrame();
    la::LightBins bins = b.gpu ? b.gpu->sizes()
                               : la::binLights(b.grid, f.view, f.proj, scene.shadingLights(),
                                               b.classes->local, b.binned);
    ViewBins v;
    v.bound = std::move(bins.bound);
    v.offsets = std::move(bins.offsets);
    v.candidates = std::move(bins.candidates);
    v.slots = bins.slots;
    v.maxBound = bins.maxBound;
    if (b.clustered) v.masks = layoutMasks(v.bound, b.slices);
    return v;
}

uint64_t addressableSlots(const ViewBinning& b) {
    return 0xffffffffull - b.classes->local.size() - b.grid.count() - 64;
}

ViewCapacity planCapacity(const ViewBins& first, const ViewBinning& b, bool manyViews,
                          const RoomLimits& limits) {
    ViewCapacity c{first.slots, first.masks.words};
    if (!manyViews) return c;
    const uint64_t tiles = b.grid.count(), range = limits.maxStorageBufferRange;
    uint64_t slotLimit =
        std::min(addressableSlots(b), range / (uint64_t(limits.numLists) * (limits.linked ? 8 : 4)));
    if (b.binned) // fp_params holds the candidates after the light indices and two offset arrays
        slotLimit = std::min(slotLimit, range / 4 - 3 * tiles - 2 * b.classes->local.size() - 64);
    const uint64_t maskWordLimit = range / 4;
    const uint64_t perTile = std::min<uint64_t>(kMinViewSlotsPerTile, b.classes->local.size());
    const uint64_t slots = std::max(kViewHeadroom * first.slots, tiles * perTile);
    c.slots = std::max(first.slots, std::min(slots, slotLimit));
    if (b.clustered) {
        // A word per slice row holds 32 lights: the floor's rows, or the headroom's.
        const uint64_t words = std::max(kViewHeadroom * first.masks.words,
                                        tiles * b.slices * ((perTile + 31) / 32));
        c.maskWords = std::max(first.masks.words, std::min(words, maskWordLimit));
    }
    return c;
}

} // namespace tp::fp
