#pragma once
// The shadow faces' meshlet cull (--cull-geometry frustum|full; docs/shadows.md, "Culling the
// faces' meshlets"; shaders/shadow/shadow_cull.comp). ShadowMaps keeps, per face, the draws
// whose bounding box may reach it (its CPU test); this pass takes every such (face, draw) pair
// as a row and tests each meshlet of the draw against the face's clip volume and its light's
// range, in one dispatch for every face of a render (the atlas, or every light's faces for the
// per-light maps of a frame). The kept meshlets become indirect draws of the row's range, with
// their count: ShadowMaps records each row as one vkCmdDrawIndexedIndirectCount over the
// scene's meshlet index buffer, with the push constants and pipeline it used before.
//
// It drops only what cannot change a shadow: a sphere wholly outside one of the face's planes
// has no fragment in the face's square (the map bit for bit), and one farther from the light
// than range * (1 + TP_SC_RANGE_FOOTPRINTS footprints) can only be the stored depth of texels
// that no receiver the light reaches compares against closer than it (the images bit for bit;
// such texels of the map may hold a farther depth or none). No normal cone: the maps render
// both faces.
//
// Two homes for what it writes: in a frame (plan(): the pass "shadow_cull", the graph's
// buffers, barriers from the declared uses), or outside the frames for the kept atlas
// (allocate(): its own buffers; the caller records the dispatch and a barrier).
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "shadow/shadow_cull.h"

namespace tp {

class GpuContext;
class SceneGpu;
struct DrawItem;

class ShadowCull {
  public:
    // Builds the scene's meshlets if nobody has. Throws RendererError where the device lacks
    // drawIndirectCount or multiDrawIndirect.
    ShadowCull(GpuContext& ctx, SceneGpu& scene);
    ~ShadowCull();
    ShadowCull(const ShadowCull&) = delete;
    ShadowCull& operator=(const ShadowCull&) = delete;

    // The rows: for each face, the draws that may reach it (ShadowMaps::cullFaces), in that
    // order. Before plan()/allocate() it sizes them; after, false when the rows outgrow what was
    // planned (in a frame: plan again); the kept atlas's own buffers grow instead.
    bool setRows(const std::vector<std::vector<const DrawItem*>>& faceDraws);
    // In a frame: its buffers (shadow_draws, shadow_draw_counts, shadow_cull_stats: exported,
    // read back by collect()) and the pass "shadow_cull". The passes that draw the rows declare
    // drawUses().
    void plan(FrameGraph& graph);
    std::vector<PassUse> drawUses() const;
    // Outside the frames: buffers of its own (ledger owner `owner`).
    void allocate(const std::string& owner);
    // The table, the set and the pipeline (after graph.compile() when planned in a frame).
    void prepare(FrameGraph* graph, const std::string& owner);
    // The dispatch (bound, with the scene set). Outside the frames the caller orders it: its
    // writes before the draws' indirect reads, and the last render's reads before it.
    void record(VkCommandBuffer cmd) const;
    // Row `firstRowOf(face) + k` (the face's k-th draw) as one indirect count draw; the caller
    // bound the pipeline, the push constants and the meshlet index buffer.
    void recordDraw(VkCommandBuffer cmd, uint32_t row) const;
    uint32_t firstRowOf(uint32_t face) const { return rowFirst_.at(face); }

    // What the compute rasterizer (shadow_raster.h) reads: the commands and counts (in a frame
    // the graph's, declared by its pass as storage reads; outside, the own buffers, valid after
    // prepare() and replaced when they grow), the rows' table and the command slots.
    ResourceHandle commands() const { return commands_; }
    ResourceHandle counts() const { return counts_; }
    VkBuffer commandBuffer() const { return commandBuffer_; }
    VkBuffer countBuffer() const { return countBuffer_; }
    VkBuffer rowBuffer() const { return table_.buffer; }
    uint32_t commandCapacity() const { return commandCapacity_; }

    // The statistics of the last render read back (in a frame: from the graph's buffer, after
    // the frames; outside: from its own). counters(): shadow_meshlets (of the rows: what an
    // unculled render draws; ShadowMaps counts their triangles), and once read
    // shadow_meshlets_submitted,
    // shadow_meshlets_culled_frustum, shadow_meshlets_culled_range, shadow_triangles_submitted.
    void collect(FrameGraph* graph);
    std::vector<std::pair<std::string, double>> counters() const;

  private:
    void writeOwnSet();
    GpuContext& ctx_;
    SceneGpu& scene_;
    std::vector<gpu::ShadowCullRow> rows_;
    std::vector<uint32_t> rowFirst_;    // by face: its first row
    std::vector<uint32_t> rowMeshlets_; // by row: the draw's meshlets (the command range)
    uint32_t rowCapacity_ = 0, commandCapacity_ = 0;
    uint64_t meshlets_ = 0;
    bool inFrame_ = false;
    ResourceHandle commands_, counts_, stats_;  // in a frame
    Buffer ownCommands_, ownCounts_, ownStats_; // outside the frames
    Buffer table_;
    std::string owner_;
    VkBuffer commandBuffer_ = VK_NULL_HANDLE, countBuffer_ = VK_NULL_HANDLE;
    PassSet set_;
    bool ownSet_ = false;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    bool collected_ = false;
    uint64_t submitted_ = 0, frustum_ = 0, range_ = 0, trianglesSubmitted_ = 0;
};

} // namespace tp
