#include "multipass_forward/light_draw_pass.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/meshlet_cull.h"
#include "multipass_forward/light_draws.h"

namespace tp::mp {
namespace {

// The commands are lights x draws (a region per light holds every draw): past this the lists
// stay on the CPU (1,024 lights x 6,553 draws; the courtyard has 17).
constexpr VkDeviceSize kMaxCommandBytes = VkDeviceSize(128) << 20;
constexpr VkDeviceSize kCommandBytes = TP_MPLD_COMMAND_WORDS * sizeof(uint32_t);

// Past one command per light and draw, the runs of reached meshlets may take this much.
constexpr VkDeviceSize kSpanBytes = VkDeviceSize(16) << 20;

// Commands a draw may take per light: as many runs of reached meshlets as kSpanBytes lets every
// light and draw have, up to TP_MPLD_MAX_SPANS_PER_DRAW (at least 1: one span). The courtyard
// (17 draws) gets 16 up to 3,084 lights.
uint32_t spansPerDraw(uint32_t lights, size_t draws) {
    const VkDeviceSize perSpan =
        std::max<VkDeviceSize>(VkDeviceSize(lights) * draws, 1) * kCommandBytes;
    return uint32_t(std::clamp<VkDeviceSize>(kSpanBytes / perSpan, 1, TP_MPLD_MAX_SPANS_PER_DRAW));
}

glm::ivec4 toIvec(const ScreenRect& r) {
    return {r.x0, r.y0, r.x1, r.y1};
}

Buffer mappedStorage(GpuContext& ctx, VkDeviceSize size, const char* name, const char* purpose) {
    return createBuffer(ctx, std::max<VkDeviceSize>(size, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        MemoryKind::Upload, {"multipass_forward", "light_draws", name, purpose});
}

} // namespace

void writeLightRows(const SceneGpu& scene, const LightPlan& plan, uint32_t lights, void* rows) {
    const std::vector<gpu::LightGpu>& sceneLights = scene.shadingLights();
    auto* out = static_cast<gpu::LightDrawLight*>(rows);
    for (size_t s = 0; s < plan.localIndex.size() && s < lights; ++s) {
        const gpu::LightGpu& l = sceneLights[plan.localIndex[s]];
        gpu::LightDrawLight row{};
        row.rect = toIvec(plan.localRect[s]);
        row.sphere = glm::vec4(l.position, l.range);
        row.flags = l.type == TP_LIGHT_DIRECTIONAL ? TP_MPLD_FLAG_ALL : 0u;
        row.light = plan.localIndex[s];
        out[s] = row;
    }
}

std::string LightDrawPass::unavailable(const GpuContext& ctx, const SceneGpu& scene,
                                       uint32_t localLights) {
    if (!ctx.caps.drawIndirectCount || !ctx.caps.drawIndirectFirstInstance)
        return "the device lacks drawIndirectCount, multiDrawIndirect or "
               "drawIndirectFirstInstance";
    const VkDeviceSize bytes = VkDeviceSize(localLights) *
                               passes::opaqueAndMaskedDraws(scene).size() * kCommandBytes;
    if (bytes > std::min<VkDeviceSize>(kMaxCommandBytes, ctx.caps.maxStorageBufferRange))
        return "lights x draws commands (" + std::to_string(bytes >> 20) +
               " MiB) past the light-draws pass's limit";
    return {};
}

LightDrawPass::LightDrawPass(GpuContext& ctx, SceneGpu& scene, uint32_t localLights,
                             bool meshletReach)
    : ctx_(ctx), scene_(scene), lights_(localLights), meshletReach_(meshletReach),
      draws_(passes::opaqueAndMaskedDraws(scene)),
      spans_(spansPerDraw(localLights, draws_.size())) {
    scene.buildMeshlets(); // the commands are spans of meshlets (light_draws.comp)
    // Runs of one cull mode in draw order: a call cannot change the cull mode between its
    // draws, and keeping the order keeps which of two coincident surfaces takes a light.
    for (size_t i = 0; i < draws_.size(); ++i) {
        if (i == 0 || draws_[i]->doubleSided != draws_[i - 1]->doubleSided) {
            runFirst_.push_back(uint32_t(i));
            runSize_.push_back(0);
            runDoubleSided_.push_back(draws_[i]->doubleSided);
        }
        ++runSize_.back();
    }
    params_ = mappedStorage(ctx, sizeof(gpu::LightDrawParams), "light_draw_params",
                            "the view's light and draw counts");
    lightRows_ = mappedStorage(ctx, VkDeviceSize(lights_) * sizeof(gpu::LightDrawLight),
                               "light_draw_lights", "per local light: its scissor and sphere");
    drawRows_ = mappedStorage(ctx, draws_.size() * sizeof(gpu::LightDrawDraw), "light_draw_draws",
                              "per opaque and masked draw: its screen rectangle and box");
}

LightDrawPass::~LightDrawPass() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

void LightDrawPass::plan(FrameGraph& graph) {
    const VkDeviceSize lights = std::max<uint32_t>(lights_, 1);
    commands_ = graph.createBuffer(
        "light_draw_commands",
        lights * std::max<VkDeviceSize>(draws_.size(), 1) * spans_ * kCommandBytes,
        "per local light a region of indexed indirect draws (per draw of the scene up to " +
            std::to_string(spans_) +
            " runs of the meshlets the light reaches), compacted per "
            "run of one cull mode");
    counts_ = graph.createBuffer("light_draw_counts",
                                 lights * std::max<VkDeviceSize>(runs(), 1) * sizeof(uint32_t),
                                 "per local light and run: its indirect draws this frame");
    meshesBuffer_ = graph.createBuffer("light_draw_meshes", lights * 2 * sizeof(uint32_t),
                                       "per local light: the opaque and masked draws it touches "
                                       "and the triangles its commands draw");
    graph.addPass("light_draws",
                  {{commands_, Use::StorageWrite, TP_MPLD_BINDING_COMMANDS},
                   {counts_, Use::StorageWrite, TP_MPLD_BINDING_COUNTS},
                   {meshesBuffer_, Use::StorageWrite, TP_MPLD_BINDING_MESHES}},
                  [this](PassContext& pc) { recordPass(pc); });
    graph.exportResource("light_draw_meshes", meshesBuffer_);
}

void LightDrawPass::prepare(FrameGraph& graph) {
    set_ = graph.createPassSet("light_draws", VK_NULL_HANDLE,
                               {{TP_MPLD_BINDING_PARAMS, params_.buffer},
                                {TP_MPLD_BINDING_LIGHTS, lightRows_.buffer},
                                {TP_MPLD_BINDING_DRAWS, drawRows_.buffer},
                                {TP_MPLD_BINDING_MESHLETS, scene_.meshletBuffer()}});
    layout_ = scene_.createPipelineLayout(set_.layout);
    pipeline_ = createComputePipeline(ctx_, "mp_light_draws_comp",
                                      scene_.specConstants(AlphaMode::Opaque), layout_, &set_);
}

void LightDrawPass::update(const LightPlan& plan) {
    const gpu::FrameUniforms& f = scene_.shadingFrame();
    gpu::LightDrawParams params{lights_,
                                uint32_t(draws_.size()),
                                runs(),
                                f.viewport.w <= 1 ? 1u : 0u, // as light_plan's shadedInsideBox
                                spans_,
                                meshletReach_ ? 1u : 0u};
    std::memcpy(params_.mapped, &params, sizeof(params));
    writeLightRows(scene_, plan, lights_, lightRows_.mapped);
    auto* drawRows = static_cast<gpu::LightDrawDraw*>(drawRows_.mapped);
    uint32_t run = 0;
    for (size_t i = 0; i < draws_.size(); ++i) {
        const DrawItem& d = *draws_[i];
        if (run + 1 < runs() && runFirst_[run + 1] == i) ++run;
        const Aabb box = scene_.toShading(d.bounds); // light_plan's visibleDraws, per draw
        gpu::LightDrawDraw row{};
        row.rect = toIvec(boxScreenRect(f, box));
        row.boxMin = glm::vec4(box.min, 0.0f);
        row.boxMax = glm::vec4(box.max, 0.0f);
        row.firstIndex = d.firstIndex;
        row.indexCount = d.indexCount;
        row.vertexOffset = d.vertexOffset;
        row.material = d.material;
        row.run = run;
        row.runFirst = runFirst_[run];
        row.firstMeshlet = d.firstMeshlet;
        row.meshletCount = d.meshletCount;
        drawRows[i] = row;
    }
}

std::vector<PassUse> LightDrawPass::drawUses() const {
    return {{commands_, Use::IndirectRead}, {counts_, Use::IndirectRead}};
}

void LightDrawPass::recordPass(PassContext& pc) {
    if (lights_ == 0 || draws_.empty()) return;
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE); // the view (frame)
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    // No push constants (meshlet_cull.cpp: a lavapipe crash): the counts are in the params.
    vkCmdDispatch(pc.cmd, (lights_ + TP_MPLD_GROUP - 1) / TP_MPLD_GROUP, 1, 1);
}

uint32_t LightDrawPass::record(PassContext& pc, uint32_t slot) const {
    const VkBuffer commands = pc.buffer(commands_).buffer, counts = pc.buffer(counts_).buffer;
    const VkDeviceSize region = VkDeviceSize(slot) * draws_.size() * spans_;
    for (uint32_t r = 0; r < runs(); ++r) {
        vkCmdSetCullMode(pc.cmd, runDoubleSided_[r] ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
        vkCmdDrawIndexedIndirectCount(
            pc.cmd, commands, (region + VkDeviceSize(runFirst_[r]) * spans_) * kCommandBytes,
            counts, (VkDeviceSize(slot) * runs() + r) * sizeof(uint32_t), runSize_[r] * spans_,
            uint32_t(kCommandBytes));
    }
    return runs();
}

void LightDrawPass::collect(FrameGraph& graph) {
    std::vector<uint8_t> bytes = readbackBuffer(ctx_, graph.buffer(meshesBuffer_));
    std::vector<uint32_t> words(size_t(lights_) * 2, 0);
    std::memcpy(words.data(), bytes.data(),
                std::min(bytes.size(), words.size() * sizeof(uint32_t)));
    meshes_.assign(lights_, 0);
    triangles_.assign(lights_, 0);
    for (uint32_t s = 0; s < lights_; ++s) {
        meshes_[s] = words[size_t(s) * 2];
        triangles_[s] = words[size_t(s) * 2 + 1];
    }
    collected_ = true;
}

} // namespace tp::mp
