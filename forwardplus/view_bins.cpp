#include "forwardplus/view_bins.h"

#include <algorithm>

#include "core/lightassign/light_bins.h"
#include "core/passes/light_binning.h"
#include "core/render/scene_gpu.h"

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

ViewCapacity planCapacity(const ViewBins& first, const ViewBinning& b, bool manyViews,
                          uint64_t slotLimit, uint64_t maskWordLimit) {
    ViewCapacity c{first.slots, first.masks.words};
    if (!manyViews) return c;
    const uint64_t tiles = b.grid.count();
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
