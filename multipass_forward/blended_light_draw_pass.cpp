#include "multipass_forward/blended_light_draw_pass.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "multipass_forward/blended_light_draws.h"
#include "multipass_forward/light_draw_pass.h"

namespace tp::mp {
namespace {

// The commands are blended draws x lights x 2: past this the blended lights stay on the CPU.
constexpr VkDeviceSize kMaxBlendedCommandBytes = VkDeviceSize(128) << 20;
constexpr VkDeviceSize kBlendedCommandBytes = TP_MPLD_COMMAND_WORDS * sizeof(uint32_t);

Buffer mappedBlendedStorage(GpuContext& ctx, VkDeviceSize size, const char* name, const char* purpose) {
    return createBuffer(ctx, std::max<VkDeviceSize>(size, 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        MemoryKind::Upload,
                        {"multipass_forward", "blended_light_draws", name, purpose});
}

uint32_t sceneBlendedDraws(const SceneGpu& scene) {
    return uint32_t(scene.drawList(DrawFilter::Blend).size());
}

} // namespace

std::string BlendedLightDrawPass::unavailable(const GpuContext& ctx, const SceneGpu& scene,
                                              uint32_t localLights, bool shadows, bool additive) {
    if (shadows) // a shadowed light's map is rendered between two lights' draws
        return "--shadows renders a light's map between the blended draws' lights";
    if (additive)
        return "--blended-lights additive (the textbook pass, kept to measure against)";
    if (!ctx.caps.dualSrcBlend) return "the device lacks dualSrcBlend";
    if (!ctx.caps.drawIndirectCount || !ctx.caps.drawIndirectFirstInstance)
        return "the device lacks drawIndirectCount, multiDrawIndirect or "
               "drawIndirectFirstInstance";
    const VkDeviceSize bytes =
        VkDeviceSize(localLights) * 2 * sceneBlendedDraws(scene) * kBlendedCommandBytes;
    if (bytes > std::min<VkDeviceSize>(kMaxBlendedCommandBytes, ctx.caps.maxStorageBufferRange))
        return "blended draws x lights x 2 commands (" + std::to_string(bytes >> 20) +
               " MiB) past the pass's limit";
    return {};
}

BlendedLightDrawPass::BlendedLightDrawPass(GpuContext& ctx, const SceneGpu& scene,
                                           uint32_t localLights)
    : ctx_(ctx), scene_(scene), lights_(localLights), blendedDraws_(sceneBlendedDraws(scene)) {
    params_ = mappedBlendedStorage(ctx, sizeof(gpu::BlendedLightDrawParams), "blended_light_draw_params",
                            "the view's light and blended draw counts");
    lightRows_ = mappedBlendedStorage(ctx, VkDeviceSize(lights_) * sizeof(gpu::LightDrawLight),
                               "blended_light_draw_lights",
                               "per local light: its rectangle, sphere and index");
    drawRows_ = mappedBlendedStorage(ctx, VkDeviceSize(blendedDraws_) * sizeof(gpu::LightDrawDraw),
                              "blended_light_draw_draws",
                              "per blended draw on screen: its rectangle, box and reversed range");
}

BlendedLightDrawPass::~BlendedLightDrawPass() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
    destroyPassSet(ctx_, lightSet_);
}

void BlendedLightDrawPass::plan(FrameGraph& graph) {
    const VkDeviceSize lights = std::max<uint32_t>(lights_, 1),
                       draws = std::max<uint32_t>(blendedDraws_, 1);
    commands_ = graph.createBuffer("blended_light_draw_commands", draws * lights * 2 * kBlendedCommandBytes,
                                   "per blended draw a region of indexed indirect draws: per "
                                   "touching light its draw and its transmittance reset");
    counts_ = graph.createBuffer("blended_light_draw_counts", draws * sizeof(uint32_t),
                                 "per blended draw: its indirect draws this frame");
    meshesBuffer_ = graph.createBuffer("blended_light_draw_meshes", lights * sizeof(uint32_t),
                                       "per local light: the blended draws it lights");
    graph.addPass("blended_light_draws",
                  {{commands_, Use::StorageWrite, TP_MPBL_BINDING_COMMANDS},
                   {counts_, Use::StorageWrite, TP_MPBL_BINDING_COUNTS},
                   {meshesBuffer_, Use::StorageWrite, TP_MPBL_BINDING_MESHES}},
                  [this](PassContext& pc) { recordPass(pc); });
    graph.exportResource("blended_light_draw_meshes", meshesBuffer_);
}

void BlendedLightDrawPass::prepare(FrameGraph& graph) {
    set_ = graph.createPassSet("blended_light_draws", VK_NULL_HANDLE,
                               {{TP_MPBL_BINDING_PARAMS, params_.buffer},
                                {TP_MPBL_BINDING_LIGHTS, lightRows_.buffer},
                                {TP_MPBL_BINDING_DRAWS, drawRows_.buffer}});
    layout_ = scene_.createPipelineLayout(set_.layout);
    pipeline_ = createComputePipeline(ctx_, "mp_blended_light_draws_comp", {}, layout_, &set_);
    // The blended light draws read the same light table (their light and rectangle).
    lightSet_ = createPassSet(ctx_, {{TP_MPBL_BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    lightSet_.pass = "blended";
    lightSet_.bindings = {{TP_MPBL_BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    writeBufferDescriptor(ctx_, lightSet_.set, TP_MPBL_BINDING_LIGHTS, lightRows_.buffer);
}

void BlendedLightDrawPass::update(const LightPlan& plan,
                                  const std::function<uint32_t(const DrawItem*)>& reversedFirst) {
    const gpu::FrameUniforms& f = scene_.shadingFrame();
    onScreen_ = uint32_t(std::min<size_t>(plan.blended.size(), blendedDraws_));
    const gpu::BlendedLightDrawParams params{lights_, onScreen_,
                                             f.viewport.w <= 1 ? 1u : 0u, 0u}; // as light_plan
    std::memcpy(params_.mapped, &params, sizeof(params));
    writeLightRows(scene_, plan, lights_, lightRows_.mapped);
    auto* rows = static_cast<gpu::LightDrawDraw*>(drawRows_.mapped);
    for (uint32_t b = 0; b < onScreen_; ++b) {
        const DrawItem& d = *plan.blended[b].draw;
        const Aabb box = scene_.toShading(d.bounds); // light_plan's visibleDraws, per draw
        const ScreenRect r = boxScreenRect(f, box);
        gpu::LightDrawDraw row{};
        row.rect = {r.x0, r.y0, r.x1, r.y1};
        row.boxMin = glm::vec4(box.min, 0.0f);
        row.boxMax = glm::vec4(box.max, 0.0f);
        row.firstIndex = reversedFirst(&d);
        row.indexCount = d.indexCount;
        row.vertexOffset = d.vertexOffset;
        row.material = d.material;
        rows[b] = row;
    }
}

std::vector<PassUse> BlendedLightDrawPass::drawUses() const {
    return {{commands_, Use::IndirectRead}, {counts_, Use::IndirectRead}};
}

void BlendedLightDrawPass::recordPass(PassContext& pc) {
    if (lights_ == 0 || blendedDraws_ == 0) return;
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    // One invocation per blended draw and one per light, for the largest view: the shader reads
    // this view's counts from the params (no push constants: meshlet_cull.cpp, a lavapipe crash).
    vkCmdDispatch(pc.cmd, (blendedDraws_ + lights_ + TP_MPBL_GROUP - 1) / TP_MPBL_GROUP, 1, 1);
}

void BlendedLightDrawPass::bindLightSet(VkCommandBuffer cmd, VkPipelineLayout layout) const {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, TP_SET_PASS, 1,
                            &lightSet_.set, 0, nullptr);
}

void BlendedLightDrawPass::record(PassContext& pc, uint32_t b) const {
    if (lights_ == 0) return; // recordPass wrote nothing: no light, no draw
    const VkDeviceSize region = VkDeviceSize(b) * 2 * lights_;
    vkCmdDrawIndexedIndirectCount(pc.cmd, pc.buffer(commands_).buffer, region * kBlendedCommandBytes,
                                  pc.buffer(counts_).buffer, VkDeviceSize(b) * sizeof(uint32_t),
                                  2 * lights_, uint32_t(kBlendedCommandBytes));
}

void BlendedLightDrawPass::collect(FrameGraph& graph) {
    std::vector<uint8_t> bytes = readbackBuffer(ctx_, graph.buffer(meshesBuffer_));
    meshes_.assign(lights_, 0);
    std::memcpy(meshes_.data(), bytes.data(),
                std::min(bytes.size(), meshes_.size() * sizeof(uint32_t)));
}

} // namespace tp::mp
