#include "visbuffer/blended_ids_pass.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/tiled_lighting.h"
#include "core/renderer/renderer.h"
#include "include/light_assign.h"
#include "visbuffer/vis_shared.h"

namespace tp::vis {

BlendedIdsPass::~BlendedIdsPass() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

namespace {

// The pool under many views (docs/visbuffer.md, "Many views"): what the views need, not what
// the CPU bound allows. The bound counts occluded and back-facing triangles and, near the
// eye, every triangle as large as the screen (a courtyard path on the H200 planned 536 million
// nodes, 4 GiB, for 124,859 fragments): so one node per sample of the screen, or twice the
// most fragments an earlier view of the session met when it overflowed (`seen`), but never
// more than this view's bound, which already holds all it can meet.
uint64_t manyViewsCapacity(uint64_t bound, uint64_t floor, uint64_t seen) {
    return std::min(bound, std::max(floor, seen));
}

} // namespace

BlendedListTargets BlendedIdsPass::plan(FrameGraph& graph, uint32_t samples, ResourceHandle depth,
                                        uint32_t capacityPercent, uint64_t bound,
                                        bool manyViews, uint64_t seen) {
    samples_ = samples;
    depth_ = depth;
    const uint64_t pixels = uint64_t(graph.width()) * graph.height();
    const uint64_t most = ctx_.caps.maxStorageBufferRange / 8;
    most_ = most;
    const uint64_t sized = manyViews ? manyViewsCapacity(bound, pixels * samples, seen) : bound;
    uint64_t capacity = capacityPercent == 0 ? std::min(sized, most)
                                             : pixels * capacityPercent / 100;
    capacity = std::max<uint64_t>(capacity, 1);
    if (capacity > most)
        throw RendererError("visbuffer: --vis-blended-capacity " + std::to_string(capacityPercent) +
                            " needs a " + std::to_string(capacity * 8) +
                            "-byte fragment pool, more than maxStorageBufferRange (" +
                            std::to_string(ctx_.caps.maxStorageBufferRange) + ") of " +
                            ctx_.info.name + "; use a lower capacity or --res");
    t_.capacity = uint32_t(capacity);
    const std::string how =
        capacityPercent == 0
            ? (manyViews && sized < bound
                   ? std::string("many views: a node per sample, or twice the fragments a view "
                                 "overflowed with")
                   : std::string("the bound of the blended triangles' screen areas")) +
                  std::string(sized > most ? ", clamped to one storage buffer" : "")
            : "--vis-blended-capacity " + std::to_string(capacityPercent) + "% of the pixels";
    t_.heads = graph.createBuffer("blended_list_heads", pixels * 4,
                                  "per pixel: its first blended fragment node + 1 (0: none)");
    t_.nodes = graph.createBuffer(
        "blended_list_nodes", capacity * 8,
        "blended fragments: id and coverage, next node (" + how + ")");
    t_.counters =
        graph.createBuffer("blended_list_counters", TP_VIS_BLEND_COUNTER_WORDS * 4,
                           "fragments met, dropped, pool capacity, most per pixel");
    graph.addPass("blended_ids_clear", {{t_.heads, Use::TransferDst}, {t_.counters, Use::TransferDst}},
                  [this, pixels](PassContext& pc) {
                      vkCmdFillBuffer(pc.cmd, pc.buffer(t_.heads).buffer, 0, pixels * 4, 0u);
                      VkBuffer c = pc.buffer(t_.counters).buffer;
                      // Each word once (two fills of one word would be a write-after-write).
                      for (uint32_t w = 0; w < TP_VIS_BLEND_COUNTER_WORDS; ++w)
                          vkCmdFillBuffer(pc.cmd, c, w * 4, 4,
                                          w == TP_VIS_BLEND_CAPACITY ? t_.capacity : 0u);
                  });
    graph.watchAfterFrame(t_.counters, 0, TP_VIS_BLEND_COUNTER_WORDS * 4); // overflowed() reads it
    // The nodes need no clear: a node is read only through a head or a node written before it.
    std::vector<PassUse> uses = {
        {depth, Use::DepthTest},
        {t_.heads, Use::StorageWrite, TP_VIS_BINDING_BLEND_HEADS},
        {t_.nodes, Use::StorageWrite, TP_VIS_BINDING_BLEND_NODES},
        {t_.counters, Use::StorageWrite, TP_VIS_BINDING_BLEND_COUNTERS}};
    if (bounds_.valid()) uses.push_back({bounds_, Use::StorageWrite, TP_LA_BLEND_BINDING_BOUNDS});
    graph.addPass("blended_ids", uses, [this](PassContext& pc) { record(pc); });
    return t_;
}

bool BlendedIdsPass::overflowed(FrameGraph& graph) {
    const std::vector<uint8_t> raw = graph.watched(t_.counters); // copied at the frame's end
    uint32_t counters[TP_VIS_BLEND_COUNTER_WORDS];
    if (raw.size() != sizeof(counters)) return false; // no frame has run
    std::memcpy(counters, raw.data(), sizeof(counters));
    if (counters[TP_VIS_BLEND_DROPPED] == 0 || t_.capacity == most_) return false;
    grownNeed_ = 2 * uint64_t(counters[TP_VIS_BLEND_APPENDED]); // met: held and dropped
    return true;
}

void BlendedIdsPass::prepare(FrameGraph& graph) {
    set_ = graph.createPassSet("blended_ids");
    layout_ = scene_.createPipelineLayout(set_.layout);
    GraphicsPipelineDesc d;
    // No material here: scene.vert's position-only variant (the same gl_Position).
    d.vertexShader = "scene_position_vert";
    d.fragmentShader = bounds_.valid() ? std::string("vis_blended_ids_bounds") +
                                             boundsConfig_.inputsSuffix() + "_frag"
                                       : std::string("vis_blended_ids_frag");
    d.specConstants = scene_.specConstants(AlphaMode::Blend);
    d.specConstants.push_back({TP_VIS_SPEC_TRIANGLE_BITS, table_.triangleBits});
    d.specConstants.push_back({TP_SPEC_SAMPLES, samples_});
    if (bounds_.valid()) {
        d.specConstants.push_back({TP_SPEC_TILE_SIZE, boundsConfig_.grid.tileSize});
        d.specConstants.push_back({TP_LA_SPEC_BLEND_BY_SUBGROUP, ctx_.reducesFragmentsBySubgroup()});
    }
    d.samples = VkSampleCountFlagBits(samples_);
    d.depthWrite = false;
    d.depthCompare = VK_COMPARE_OP_GREATER; // in front of the opaque depth, as the reference's blend
    d.layout = layout_;
    d.passSet = &set_;
    pipeline_ = createGraphicsPipeline(ctx_, d);
}

void BlendedIdsPass::record(PassContext& pc) {
    DepthTarget depth{depth_, {}, false, true};
    beginRendering(pc, {}, depth);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    scene_.bindIndexBuffer(pc.cmd);
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    for (const TableDraw& t : table_.blended)
        recordDraw(pc.cmd, layout_, *t.item, t.row); // the row in the push constant's pad0
    endRendering(pc);
}

} // namespace tp::vis
