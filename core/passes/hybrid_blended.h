#pragma once
// The blended half of a pipeline that lights its opaque surfaces in tiled compute (deferred,
// the visibility buffer): the hybrid forward path. Tiled lighting writes per-tile
// transparent light lists (blended_lists.h) culled against the blended depth bounds
// (blended_bounds.h), and the blended forward pass (blended_forward.h) draws the blended
// materials back to front from them. This class plans the lists (and, clustered, their slice
// rows), the bounds pass and the forward pass in the order the frame needs them, and turns
// the tile statistics into the pipeline's counters and heat map, so each composing pipeline
// holds none of it.
#include <cstdint>
#include <string>
#include <vector>

#include "core/image/image.h"
#include "core/passes/blended_bounds.h"
#include "core/passes/blended_forward.h"
#include "core/passes/tiled_lighting.h"

namespace tp {

struct RendererStats;

class HybridBlended {
  public:
    HybridBlended(GpuContext& ctx, SceneGpu& scene)
        : ctx_(ctx), scene_(scene), bounds_(ctx, scene), forward_(ctx, scene) {}

    // First (before tiled lighting plans): the transparent lists into t.transparentLists and
    // t.listOffsets: light indices, each tile's run sized from its candidates (binned: their
    // bound comes from `lighting`), 4 bytes a candidate. composited (the tiled pass composites
    // the blended fragments, batch by batch of candidates: the visibility buffer's
    // --vis-blended compute) and binned: bitmasks over the candidates instead, a bit each.
    // slices > 0 with sliceRows: the clustered slice rows over the lists too. manyViews: the
    // lists (and slice rows) get headroom for later views (blended_lists.h).
    void planLists(FrameGraph& graph, TiledLighting& lighting, TiledLightingTargets& t, bool binned,
                   uint32_t slices, bool sliceRows, bool manyViews = false,
                   bool composited = false);
    // A new view, after lighting.updateView: the lists' offsets for it into t.listOffsets and
    // tiled lighting's buffer. false when they need more slots than planned (a replan). GPU
    // binning: nothing (the frame lays them out; TiledLighting::overflowed checks the room).
    bool updateLists(TiledLighting& lighting, TiledLightingTargets& t);
    // Then, after the pass that writes the opaque depth: the blended depth bounds.
    ResourceHandle planBounds(FrameGraph& graph, const la::BlendedBoundsConfig& config);
    // Last, after tiled lighting: the forward pass over the lists (t.bounds: planBounds's).
    // Optional: a pipeline that composites blended surfaces itself (the visibility buffer's
    // --vis-blended compute) uses only the lists and the bounds.
    void planForward(FrameGraph& graph, const BlendedForwardTargets& t, uint32_t slices);
    // GPU binning: the frame lays out the lists (TiledLighting::publishListWords), in the
    // planned capacity.
    void prepare(FrameGraph& graph, TiledLighting& lighting);

    // Clustered: the slice rows tiled lighting writes (invalid otherwise).
    ResourceHandle sliceRows() const { return sliceRows_; }

    // From the tile statistics (uvec4 per tile: opaque, transparent lights found, ...) and the
    // lists' offsets: the transparent counters, and the transparent lights-per-tile heat map.
    void addStats(RendererStats& s, const std::vector<uint32_t>& tileStats,
                  const std::vector<uint32_t>& listOffsets) const;
    ImageRGBA heatMap(const la::TileGrid& grid, const std::vector<uint32_t>& tileStats,
                      const std::vector<uint32_t>& listOffsets) const;

  private:
    GpuContext& ctx_;
    SceneGpu& scene_;
    la::BlendedBounds bounds_;
    BlendedForwardPass forward_;
    ResourceHandle sliceRows_;
    uint64_t slots_ = 0;    // the current view's
    uint64_t capacity_ = 0; // planned
    bool binned_ = false; // the lists' runs are sized from the tiled pass's candidates
    bool masks_ = false;  // binned and composited: the lists are bitmasks over the candidates
    bool forwardPlanned_ = false;
};

struct DebugImage;

// --debug's images of the tiled lighting pass, named alike for every surface source:
// lights_per_tile, lights_per_tile_transparent (`blended`: a blended scene's lists, or null),
// edge_mask and roughness_metallic (TP_DEBUG's image split, splitDebugImage).
void appendTiledLightingDebug(GpuContext& ctx, FrameGraph& graph, const TiledLightingTargets& t,
                              const std::vector<uint32_t>& tileStats, const HybridBlended* blended,
                              std::vector<DebugImage>& out);

// Column `c` of per-tile statistics stored as uvec4 per tile.
std::vector<uint32_t> tileStatColumn(const std::vector<uint32_t>& stats, uint32_t c);

} // namespace tp
