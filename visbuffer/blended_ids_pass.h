#pragma once
// The blended fragment lists of --vis-blended compute (passes "blended_ids_clear" and
// "blended_ids"): the blended draws, back to front as the reference draws them, depth-tested
// against the visibility depth without writing it, append each fragment's id and coverage to
// its pixel's list (shaders/visbuffer/blended_ids.frag). The pool holds a fixed number of
// fragments (--vis-blended-capacity); a fragment past it is counted, not stored. The resolve
// (the tiled lighting pass, shaders/visbuffer/vis_blend.glsl) composites the lists.
#include <cstdint>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/passes/blended_bounds.h"
#include "visbuffer/draw_table.h"

namespace tp {

class GpuContext;
class SceneGpu;

namespace vis {

struct BlendedListTargets {
    ResourceHandle heads;    // uint per pixel: first node + 1
    ResourceHandle nodes;    // uvec2 per fragment: id | coverage << 24, next + 1
    ResourceHandle counters; // vis_shared.h: TP_VIS_BLEND_*
    uint32_t capacity = 0;   // nodes
};

class BlendedIdsPass {
  public:
    BlendedIdsPass(GpuContext& ctx, SceneGpu& scene, const DrawTable& table)
        : ctx_(ctx), scene_(scene), table_(table) {}
    ~BlendedIdsPass();
    // depth: the visibility depth (per sample under MSAA). capacityPercent: nodes in percent
    // of the pixels, or 0: `bound` nodes (fragment_bound.h), clamped to what one storage
    // buffer can hold (a fragment past it is then dropped and counted). Throws RendererError
    // when an explicit capacity exceeds maxStorageBufferRange. manyViews (capacity 0): sized
    // from need, not from the bound (manyViewsCapacity), and grown on a counted overflow.
    BlendedListTargets plan(FrameGraph& graph, uint32_t samples, ResourceHandle depth,
                            uint32_t capacityPercent, uint64_t bound, bool manyViews = false,
                            uint64_t seen = 0);
    // After a view's frames (many views): whether the pool dropped fragments it could have
    // held had it been larger (not when it is already one whole storage buffer); then
    // grownNeed() is what it should hold. Reads the pass's counters back.
    bool overflowed(FrameGraph& graph);
    uint64_t grownNeed() const { return grownNeed_; }
    // Whether a new view whose bound is `bound` fits the planned pool: a pool clamped to one
    // storage buffer already holds the most a plan could give it (drops there are counted).
    bool fits(uint64_t bound) const { return bound <= t_.capacity || t_.capacity == most_; }
    void prepare(FrameGraph& graph);
    // Before plan(): the pass's fragments also record the blended depth bounds into `buffer`
    // (a BlendedBounds planned with drawnElsewhere, whose config says the rate).
    void recordBounds(ResourceHandle buffer, const la::BlendedBoundsConfig& config) {
        bounds_ = buffer;
        boundsConfig_ = config;
    }

  private:
    void record(PassContext& pc);
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DrawTable& table_;
    uint32_t samples_ = 1;
    ResourceHandle depth_;
    ResourceHandle bounds_; // recordBounds()
    la::BlendedBoundsConfig boundsConfig_;
    BlendedListTargets t_;
    uint64_t most_ = 0; // nodes one storage buffer holds
    uint64_t grownNeed_ = 0;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace vis
} // namespace tp
