#pragma once
// Tiled lighting of a surface source in compute (one workgroup per tile: depth bounds, light
// culling into shared memory, shading of the tile's pixels; per sample on MSAA edges only).
// Also writes per-tile statistics and, for blended scenes, the transparent light lists the
// hybrid blended pass (blended_forward.h) reads. The surface attributes come from a
// SurfaceSource: deferred's G-buffer (shaders/deferred/gbuffer_read.glsl) or the visibility
// buffer's ids (shaders/visbuffer/vis_read.glsl), each with its own reader and shader family,
// sharing the culling, batching, lists and statistics.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/image/image.h"
#include "core/lightassign/knobs.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_grid.h"
#include "core/passes/light_binning.h"
#include "core/passes/lights_ubo.h"
#include "core/passes/tile_depth_bounds.h"
#include "passes/tiled_lighting.h"

namespace tp {

// Lights per tiled lighting dispatch. lavapipe (gallivm) ends a shader invocation after
// 65,535 loop iterations in total, counted over every loop it runs
// (LP_MAX_TGSI_LOOP_ITERATIONS): the rest of its work is silently skipped. An invocation
// shades (tileSize / 8)^2 pixels, each up to `samples` times, with every light of its
// tile's list, so a batch holds at most 32,768 / (pixels * samples) lights (half the
// limit: the other loops - depth bounds, culling, transparent lists - stay far below the
// rest) and never more than the shared list (TP_TL_TILE_LIGHT_CAPACITY).
uint32_t tiledLightBatch(uint32_t tileSize, uint32_t samples);

// The per-tile statistics the pass writes (uvec4 per tile: opaque lights, transparent lights,
// edge pixels, overflow), summed over the tiles.
struct TileStatTotals {
    double tiles = 0, lights = 0, maxLights = 0, edges = 0, overflow = 0;
    double meanLights() const { return tiles > 0 ? lights / tiles : 0.0; }
};
TileStatTotals sumTileStats(const std::vector<uint32_t>& stats);

// --debug's image (debug_edge_rm: edge mask, roughness, metallic) as two display images: the
// edge mask in grey, roughness and metallic in red and green.
struct EdgeAndRoughMetal {
    ImageRGBA edge, roughMetal;
};
EdgeAndRoughMetal splitDebugImage(const ImageRGBA& debug);

class GpuContext;
class SceneGpu;
class ShadowMaps;

// Planned for many views (RenderSettings::manyViews): a list sized from the camera and the
// lights gets kViewHeadroom times the first view's need (at least `floor`, never more than
// `most`: what the worst view can need, or what one buffer can hold), so that ordinary camera
// moves and light motion fit it; a view that needs more is planned again (counted). A single
// view: exactly its need.
constexpr uint64_t kViewHeadroom = 4;
uint64_t viewCapacity(uint64_t need, uint64_t floor, uint64_t most, bool manyViews);

// Where the lit surfaces' attributes come from. The shader family reads them through its
// surface reader (shaders/deferred/gbuffer_read.glsl for the G-buffer) at the bindings given
// here; the pass names the family's variants from the flags below.
struct SurfaceSource {
    std::string
        shaderFamily; // variants FAMILY_m<M>_e<E>_t<T>_d<D>[_h16]_comp, FAMILY_lists_m<M>_comp
    std::vector<PassUse> attributes; // sampled images, each with its binding
    ResourceHandle depth;            // per-sample depth: the tiles' bounds, positions from depth
    uint32_t samples = 1;
    bool emissive = false;    // an emissive attribute is among them
    bool everySample = false; // the material per sample (--msaa-shading sample): lit per sample
    std::vector<SpecConstant> constants; // the source's own (the G-buffer's layout)
    // Static buffers the reader binds in the pass's set (a visibility buffer's index buffer
    // and draw table): uploaded before any frame, so no barrier is tracked for them.
    std::vector<ExternalBuffer> buffers;
    // Light evaluations per pixel and batch light the reader may make, when more than
    // `samples` (the visibility buffer's blended fragments): the batches are sized for it.
    uint32_t evaluationsPerPixel = 0;
};

// What the pass writes. Invalid handles are left out: hdrMsaa (per-sample radiance, blended
// scenes under MSAA), transparentLists (blended scenes), debug (--debug).
struct TiledLightingTargets {
    la::TileGrid grid;
    ResourceHandle hdr, hdrMsaa;
    VkFormat hdrFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    ResourceHandle tileStats, transparentLists, debug;
    std::vector<uint32_t> listOffsets; // transparent lists: tileCount + 1 run offsets
    // The shadow atlas (ShadowMaps::Residency::Atlas, planned before this pass) the shading
    // samples when it is enabled (--shadows): the shaders' _shadow twins, set TP_SET_SHADOW.
    // Null, or not enabled: the pass is what it was before shadows existed.
    const ShadowMaps* shadows = nullptr;
};

class TiledLighting {
  public:
    // binned (--light-cull binned): each tile tests only its candidates
    // (core/lightassign/light_bins.h). slices > 0 (--light-assign clustered): each sample takes
    // only its depth slice's lights. gpuBinning (--light-bin resolved to gpu; binned only): pass
    // light_binning builds the candidates every frame (core/passes/light_binning.h).
    // manyViews: the candidates get headroom (viewCapacity) for the views after the first.
    TiledLighting(GpuContext& ctx, SceneGpu& scene, bool debug, bool binned, uint32_t slices,
                  bool gpuBinning = false, bool manyViews = false)
        : ctx_(ctx), scene_(scene), debug_(debug), binned_(binned), slices_(slices),
          gpuBinning_(binned && gpuBinning), manyViews_(manyViews) {}
    ~TiledLighting();
    // --tile-group (core/lightassign/knobs.h), before plan: the workgroup's edge.
    void setGroup(la::TileGroup group) { group_ = group; }
    // listsOnly: volumes lighting shades the opaque surfaces; only the transparent lists
    // (and the tile statistics) are built here.
    // transparentMasks (clustered blended scenes, else invalid): the slice rows over the
    // transparent lists that this pass writes for the blended pass (passes/tiled_lighting.h).
    // blendBounds (blended scenes): the blended depth bounds the transparent lists are culled
    // against (core/passes/blended_bounds.h).
    void plan(FrameGraph& graph, const SurfaceSource& source, const TiledLightingTargets& t,
              bool listsOnly = false, ResourceHandle transparentMasks = {},
              ResourceHandle blendBounds = {});
    void prepare(FrameGraph& graph);
    // Binned: each tile's candidate count (per point/spot light rectangle covering it; the
    // transparent lists are sized from it too) for the scene's current view, on the CPU or
    // (gpuBinning) by the plan-time run of the GPU binning: first for the planned view (plan()
    // bins if nobody asked before), then for each new one by updateView.
    const std::vector<uint32_t>& bound(const la::TileGrid& grid, const std::string& owner);
    // A new view (camera or lights moved; SceneGpu holds them), CPU binning: the lights binned
    // again for it and the candidates' header, offsets and runs uploaded into the planned
    // buffer, so bound() and the next recording follow; false when the view does not fit the
    // plan (more candidate slots than the buffer holds, other directional lights). GPU
    // binning: only the slab planes (light_binning.h: followView); the frame writes the
    // offsets and runs, and overflowed() checks the room after the view's frames (bound()
    // stays the planned view's).
    bool updateView(FrameGraph& graph);
    // The transparent lists' offsets of a new view (HybridBlended::updateLists), uploaded.
    void setListOffsets(const std::vector<uint32_t>& offsets);
    // GPU binning (after prepare): the frame lays out the transparent lists itself, in `room`
    // words, instead of setListOffsets per view (light_binning.h: publishWords): a word per
    // candidate (light indices), or (masks) a bit per candidate.
    void publishListWords(uint64_t room, bool masks);
    // GPU binning, after a view's frames: whether it needed more than the plan holds (the
    // candidates' room, the longest run, the transparent lists' words); the caller plans again.
    bool overflowed(FrameGraph& graph);
    // GPU binning, after a frame: its layout read back (candidates(), listOffsets()), for
    // statistics.
    void collect(FrameGraph& graph);
    const std::vector<uint32_t>& listOffsets() const { return t_.listOffsets; }
    // Light-vs-tile tests the culling makes (binned: the candidates; all: lights x tiles).
    uint64_t candidates() const { return candidateCount_; }
    bool gpuBinning() const { return gpuBinning_; }
    // GPU binning: its counters and its passes' counted work for the last collected frame
    // (GpuBinning::addStats).
    void addBinningWork(RendererStats& s) const {
        if (binning_) binning_->addStats(s, bins_.slots);
    }
    // The lights' uniform-buffer copy (after plan), kept up to date by updateView: the blended
    // forward pass binds it too.
    const LightsUbo& lightsUbo() const { return *lightsUbo_; }
    // Dispatches the last recorded frame made (one per batch of lights).
    uint32_t batches() const { return batches_; }

  private:
    void record(PassContext& pc);
    void dispatch(VkCommandBuffer cmd, uint32_t first, uint32_t end);
    uint32_t lightBatch() const;
    std::string passName() const;
    std::string shaderName() const;
    bool shadowed() const; // shading that samples the shadow atlas
    void uploadCandidates(FrameGraph& graph);
    void bin(); // bins_ for the scene's current view and lights
    // The candidates buffer's words for bins_: header, directional lights, offsets, then the
    // runs (CPU binning; GPU binning: zeros, the frame writes them).
    std::vector<uint32_t> candidateWords(const la::LightClasses& classes);
    GpuContext& ctx_;
    SceneGpu& scene_;
    bool debug_;
    bool binned_ = true;
    uint32_t batches_ = 0;
    uint32_t slices_ = 0;
    bool gpuBinning_ = false;
    bool manyViews_ = false;
    la::TileGroup group_ = la::TileGroup::Auto;
    uint64_t slotCapacity_ = 0;          // binned: candidate run slots the buffer holds
    std::vector<uint32_t> directional_;  // binned: the directional lights planned for
    std::unique_ptr<la::GpuBinning> binning_; // gpuBinning_: the light_binning pass
    std::unique_ptr<TileDepthBounds> depthBounds_; // the tile_depth_bounds pass before this one
    la::LightBins bins_; // binned: the runs (CPU) or their sizes (GPU: no candidates)
    bool binnedOnce_ = false;
    bool listsOnly_ = false;
    ResourceHandle transparentMasks_;
    uint32_t maxCandidates_ = 0; // binned: the most candidates of any tile (the batches' range)
    uint64_t candidateCount_ = 0;
    SurfaceSource source_;
    TiledLightingTargets t_;
    bool msaa() const { return source_.samples > 1; }
    PassSet set_;
    Buffer listOffsets_; // transparent lists' per-tile offsets (blended scenes)
    Buffer candidates_;  // binned culling's candidates (a 16-byte header otherwise)
    Buffer noMasks_;     // blended scenes, tiled: a 16-byte stand-in for the unused slice rows
    std::optional<LightsUbo> lightsUbo_; // the lights' uniform-buffer copy (a CPU device reads it)
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace tp
