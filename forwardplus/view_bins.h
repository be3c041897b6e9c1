#pragma once
// What Forward+ derives from the camera and the lights on the CPU, per view (plan once, render
// many views: Renderer::updateView): every local light's conservative tile rectangle counted
// per tile (the compact layout's bound and offsets), the binned candidates (--light-bin cpu)
// or the GPU binning's sizing run (--light-bin gpu: at plan time only; later views are laid
// out by the frame, tiled and clustered alike), and the clusters' mask rows. A plan sizes
// its buffers from the first view: exactly, or with RenderSettings::manyViews kViewHeadroom
// times it, so that ordinary camera moves and light motion lay out inside the same buffers; a
// view that needs more is refused (ViewCapacity::holds) and the renderer is planned again,
// counted (view_replans). docs/forwardplus.md, "Many views".
#include <cstdint>
#include <vector>

#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_grid.h"
#include "forwardplus/light_lists.h"

namespace tp {
class GpuContext;
class SceneGpu;
namespace la {
class GpuBinning;
}
} // namespace tp

namespace tp::fp {

// Many views: the lists' room over the first view's need.
constexpr uint64_t kViewHeadroom = 2;
// ... and at least this many slots per tile (as many as there are local lights, if fewer), so
// that a first view with few lights in sight (the sky) does not leave the next one no room.
constexpr uint64_t kMinViewSlotsPerTile = 32;

// One view's bins.
struct ViewBins {
    std::vector<uint32_t> bound;      // per tile: local lights whose rectangle covers it
    std::vector<uint32_t> offsets;    // compact layout of `bound` (tileCount + 1)
    std::vector<uint32_t> candidates; // CPU binning, binned culling: each tile's run
    uint64_t slots = 0;               // the bound's total (unclamped)
    uint32_t maxBound = 0;            // the longest run
    MaskLayout masks;                 // clustered: the slice rows' word offsets
};

struct ViewBinning {
    la::TileGrid grid;
    const la::LightClasses* classes = nullptr;
    bool binned = false;    // --light-cull binned: the candidates too
    bool clustered = false; // mask rows
    uint32_t slices = 0;
    la::GpuBinning* gpu = nullptr; // --light-bin gpu: its sizing run (plan time; no candidates)
};

// The scene's current (uploaded, camera-relative) view and lights, binned.
ViewBins binView(const SceneGpu& scene, const ViewBinning& b);

// What a plan holds: slots of one list kind (also the binned candidates' room), mask words.
struct ViewCapacity {
    uint64_t slots = 0, maskWords = 0;
    bool holds(const ViewBins& v) const { return v.slots <= slots && v.masks.words <= maskWords; }
};

// The slots fp_params' 32-bit offsets address (after the light indices and tile offsets).
uint64_t addressableSlots(const ViewBinning& b);

// What the buffers the room goes into hold: the index buffer's lists (linked: 8-byte nodes),
// fp_params' candidates, the mask words, each up to maxStorageBufferRange.
struct RoomLimits {
    uint64_t maxStorageBufferRange = 0;
    uint32_t numLists = 1;
    bool linked = false;
};

// The first view's need, or with `manyViews` the headroom over it: kViewHeadroom times it, at
// least kMinViewSlotsPerTile per tile, kept within the limits (never below the need, which the
// sizing refuses on its own).
ViewCapacity planCapacity(const ViewBins& first, const ViewBinning& b, bool manyViews,
                          const RoomLimits& limits);

} // namespace tp::fp
