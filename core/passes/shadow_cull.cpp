#include "core/passes/shadow_cull.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/renderer/renderer.h"
#include "shadow/shadow_raster.h"

namespace tp {
namespace {
constexpr VkDeviceSize kCommandBytes = TP_SC_COMMAND_WORDS * sizeof(uint32_t);

// The rows padded to `capacity` with rows of no meshlets that start where the last real one
// ends, so the table stays sorted by firstCommand (shadow_raster.comp bisects it).
std::vector<gpu::ShadowCullRow> paddedRows(const std::vector<gpu::ShadowCullRow>& rows,
                                           uint32_t capacity, uint64_t commands) {
    std::vector<gpu::ShadowCullRow> padded = rows;
    gpu::ShadowCullRow pad{};
    pad.firstCommand = uint32_t(commands);
    padded.resize(capacity, pad);
    return padded;
}
} // namespace

ShadowCull::ShadowCull(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {
    if (!ctx_.caps.drawIndirectCount)
        throw RendererError("--cull-geometry: device '" + ctx_.info.name +
                            "' lacks drawIndirectCount or multiDrawIndirect; use "
                            "--cull-geometry none");
    scene_.buildMeshlets(); // fills the draws' meshlet ranges in place
}

ShadowCull::~ShadowCull() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    if (ownSet_) destroyPassSet(ctx_, set_); // the graph's sets are the graph's
}

bool ShadowCull::setRows(const std::vector<std::vector<const DrawItem*>>& faceDraws) {
    rows_.clear();
    rowFirst_.clear();
    rowMeshlets_.clear();
    meshlets_ = 0;
    uint32_t commands = 0;
    for (uint32_t face = 0; face < faceDraws.size(); ++face) {
        rowFirst_.push_back(uint32_t(rows_.size()));
        for (const DrawItem* d : faceDraws[face]) {
            gpu::ShadowCullRow r{};
            r.firstMeshlet = d->firstMeshlet;
            r.meshletCount = d->meshletCount;
            r.firstCommand = commands;
            r.vertexOffset = d->vertexOffset;
            r.face = face;
            r.material = d->material;
            r.flags = d->alphaMode == AlphaMode::Mask ? TP_SR_FLAG_MASKED : 0u;
            rows_.push_back(r);
            rowMeshlets_.push_back(d->meshletCount);
            commands += d->meshletCount;
            meshlets_ += d->meshletCount;
        }
    }
    collected_ = false;
    const bool fits = rows_.size() <= rowCapacity_ && commands <= commandCapacity_;
    if (!table_.buffer) return true; // not planned yet: plan() or allocate() sizes them
    if (!fits && inFrame_) return false;
    if (!fits) { // the kept atlas: its own buffers grow
        allocate(owner_);
        table_ = Buffer();
        prepare(nullptr, owner_);
        return true;
    }
    // Rows of no meshlets: a count of 0, never drawn.
    const std::vector<gpu::ShadowCullRow> padded = paddedRows(rows_, rowCapacity_, meshlets_);
    uploadBufferData(ctx_, table_, padded.data(), padded.size() * sizeof(gpu::ShadowCullRow));
    return true;
}

void ShadowCull::plan(FrameGraph& graph) {
    inFrame_ = true;
    rowCapacity_ = std::max<uint32_t>(uint32_t(rows_.size()), 1);
    commandCapacity_ = std::max<uint32_t>(uint32_t(meshlets_), 1);
    commands_ = graph.createBuffer("shadow_draws", commandCapacity_ * kCommandBytes,
                                   "per kept meshlet of a shadow face: an indexed indirect draw "
                                   "(5 words), per (face, draw) a range");
    counts_ = graph.createBuffer("shadow_draw_counts", rowCapacity_ * sizeof(uint32_t),
                                 "per (face, draw): its indirect draws this frame");
    stats_ = graph.createBuffer("shadow_cull_stats", rowCapacity_ * sizeof(gpu::ShadowCullStats),
                                "per (face, draw): meshlets kept, culled by the face's frustum "
                                "and by the light's range; triangles kept");
    graph.addPass("shadow_cull",
                  {{commands_, Use::StorageWrite, TP_SC_BINDING_COMMANDS},
                   {counts_, Use::StorageWrite, TP_SC_BINDING_COUNTS},
                   {stats_, Use::StorageWrite, TP_SC_BINDING_STATS}},
                  [this](PassContext& pc) { record(pc.cmd); });
    graph.exportResource("shadow_cull_stats", stats_);
}

std::vector<PassUse> ShadowCull::drawUses() const {
    return {{commands_, Use::IndirectRead}, {counts_, Use::IndirectRead}};
}

void ShadowCull::allocate(const std::string& owner) {
    owner_ = owner;
    rowCapacity_ = std::max<uint32_t>(uint32_t(rows_.size()), 1);
    commandCapacity_ = std::max<uint32_t>(uint32_t(meshlets_), 1);
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                     VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                                     VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    const std::string pass = "shadow_maps (once)";
    ownCommands_ = createBuffer(ctx_, commandCapacity_ * kCommandBytes, usage, MemoryKind::Device,
                                {owner, pass, "shadow_draws",
                                 "per kept meshlet of a shadow face: an indexed indirect draw, "
                                 "per (face, draw) a range (kept for the kept atlas's renders)"});
    ownCounts_ = createBuffer(ctx_, rowCapacity_ * sizeof(uint32_t), usage, MemoryKind::Device,
                              {owner, pass, "shadow_draw_counts", "per (face, draw): its draws"});
    ownStats_ =
        createBuffer(ctx_, rowCapacity_ * sizeof(gpu::ShadowCullStats), usage, MemoryKind::Device,
                     {owner, pass, "shadow_cull_stats",
                      "per (face, draw): meshlets kept, culled by frustum and range"});
}

void ShadowCull::prepare(FrameGraph* graph, const std::string& owner) {
    const std::vector<gpu::ShadowCullRow> padded = paddedRows(rows_, rowCapacity_, meshlets_);
    table_ =
        createBufferWithData(ctx_, padded.data(), padded.size() * sizeof(gpu::ShadowCullRow),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             {owner, "", "shadow_cull_rows",
                              "per (face, draw) a shadow face may see: its meshlets, its "
                              "range of commands"});
    const std::vector<ExternalBuffer> externals = {{TP_SC_BINDING_MESHLETS, scene_.meshletBuffer()},
                                                   {TP_SC_BINDING_ROWS, table_.buffer},
                                                   {TP_SC_BINDING_FACES, scene_.shadowFaces()}};
    if (inFrame_) {
        if (!set_.set) set_ = graph->createPassSet("shadow_cull", VK_NULL_HANDLE, externals);
        commandBuffer_ = graph->buffer(commands_).buffer;
        countBuffer_ = graph->buffer(counts_).buffer;
    } else {
        if (!ownSet_) { // written again when the buffers grow (setRows)
            std::vector<SetBinding> bindings;
            for (uint32_t b : {TP_SC_BINDING_COMMANDS, TP_SC_BINDING_COUNTS, TP_SC_BINDING_STATS,
                               TP_SC_BINDING_MESHLETS, TP_SC_BINDING_ROWS, TP_SC_BINDING_FACES})
                bindings.push_back({b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
            set_ = createPassSet(ctx_, bindings);
            set_.pass = "shadow_maps (once)";
            set_.bindings = bindings; // what the shader is checked against
            ownSet_ = true;
        }
        writeBufferDescriptor(ctx_, set_.set, TP_SC_BINDING_COMMANDS, ownCommands_.buffer);
        writeBufferDescriptor(ctx_, set_.set, TP_SC_BINDING_COUNTS, ownCounts_.buffer);
        writeBufferDescriptor(ctx_, set_.set, TP_SC_BINDING_STATS, ownStats_.buffer);
        for (const ExternalBuffer& e : externals)
            writeBufferDescriptor(ctx_, set_.set, e.binding, e.buffer);
        commandBuffer_ = ownCommands_.buffer;
        countBuffer_ = ownCounts_.buffer;
    }
    if (!pipeline_) {
        layout_ = scene_.createPipelineLayout(set_.layout);
        pipeline_ = createComputePipeline(ctx_, "shadow_cull_comp",
                                          scene_.specConstants(AlphaMode::Opaque), layout_, &set_);
    }
}

void ShadowCull::record(VkCommandBuffer cmd) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    scene_.bindSceneSet(cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1, &set_.set,
                            0, nullptr);
    // No push constants (the lavapipe crash MeshletCull::record describes): the shader takes the
    // rows from its table's length. At most 65,535 groups per row of the grid.
    const uint32_t x = std::min(rowCapacity_, 65535u);
    vkCmdDispatch(cmd, x, (rowCapacity_ + x - 1) / x, 1);
}

void ShadowCull::recordDraw(VkCommandBuffer cmd, uint32_t row) const {
    if (rowMeshlets_.at(row) == 0) return;
    vkCmdDrawIndexedIndirectCount(
        cmd, commandBuffer_, VkDeviceSize(rows_[row].firstCommand) * kCommandBytes, countBuffer_,
        VkDeviceSize(row) * sizeof(uint32_t), rowMeshlets_[row], uint32_t(kCommandBytes));
}

void ShadowCull::collect(FrameGraph* graph) {
    const std::vector<uint8_t> bytes =
        readbackBuffer(ctx_, inFrame_ ? graph->buffer(stats_) : ownStats_);
    std::vector<gpu::ShadowCullStats> stats(rows_.size());
    std::memcpy(stats.data(), bytes.data(), stats.size() * sizeof(gpu::ShadowCullStats));
    submitted_ = frustum_ = range_ = trianglesSubmitted_ = 0;
    for (const gpu::ShadowCullStats& s : stats) {
        submitted_ += s.submitted;
        frustum_ += s.frustumCulled;
        range_ += s.rangeCulled;
        trianglesSubmitted_ += s.triangles;
    }
    collected_ = true;
}

std::vector<std::pair<std::string, double>> ShadowCull::counters() const {
    std::vector<std::pair<std::string, double>> c = {{"shadow_meshlets", double(meshlets_)}};
    if (!collected_) return c;
    c.push_back({"shadow_meshlets_submitted", double(submitted_)});
    c.push_back({"shadow_meshlets_culled_frustum", double(frustum_)});
    c.push_back({"shadow_meshlets_culled_range", double(range_)});
    c.push_back({"shadow_triangles_submitted", double(trianglesSubmitted_)});
    return c;
}

} // namespace tp
