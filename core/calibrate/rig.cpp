#include "core/calibrate/rig.h"

#include <algorithm>

#include "core/gpu/barriers.h"
#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/vk_check.h"

namespace tp::calibrate {
namespace {

using gpu::CalPush;

constexpr VkShaderStageFlags kPushStages =
    VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr VkFormat kTextureFormat = VK_FORMAT_R8G8B8A8_UNORM;

// Linear for the texture's fetches; nearest for the 4x depth, whose format need not filter
// (texelFetch never does, but a linear sampler on it is invalid).
VkSampler createRepeatSampler(GpuContext& ctx, VkFilter filter) {
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = filter;
    si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    si.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(ctx.device, &si, nullptr, &sampler));
    return sampler;
}

// Zeros in the buffers (what the reads sum, so no result is ever written back), grey in the
// texture, which is then left for sampling.
void fill(GpuContext& ctx, Rig& rig) {
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, rig.src.buffer, 0, VK_WHOLE_SIZE, 0u);
        vkCmdFillBuffer(cmd, rig.dst.buffer, 0, VK_WHOLE_SIZE, 0u);
        imageBarrier(cmd, rig.texture.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT);
        const VkClearColorValue grey{{0.5f, 0.5f, 0.5f, 1.0f}};
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, rig.texture.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &grey, 1, &all);
        imageBarrier(cmd, rig.texture.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
        // The 4x depth at 0.5 (its reads sum it; nothing is written back).
        const VkImageSubresourceRange depth{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        imageBarrier(cmd, rig.depthMsaa4.image, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, depth);
        const VkClearDepthStencilValue half{0.5f, 0};
        vkCmdClearDepthStencilImage(cmd, rig.depthMsaa4.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                    &half, 1, &depth);
        imageBarrier(cmd, rig.depthMsaa4.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, depth);
    });
}

std::vector<VkFormat> colorFormats(const BenchDraw& d) {
    std::vector<VkFormat> out;
    if (d.color == VK_FORMAT_UNDEFINED) return out;
    out.push_back(d.color);
    out.insert(out.end(), d.moreColors.begin(), d.moreColors.end());
    return out;
}

void createLayout(Rig& rig) {
    VkDescriptorSetLayoutCreateInfo empty{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    VK_CHECK(vkCreateDescriptorSetLayout(rig.ctx.device, &empty, nullptr, &rig.emptySet));
    rig.layout = createPassPipelineLayout(rig.ctx, rig.emptySet, rig.set.layout, kPushStages,
                                          sizeof(CalPush));
}

void beginRendering(VkCommandBuffer cmd, const Targets& t, uint32_t size) {
    std::vector<VkRenderingAttachmentInfo> colors;
    for (const Image& image : t.colors) {
        VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        color.imageView = image.view;
        color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR; // blending adds to something defined
        color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        colors.push_back(color);
    }
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = t.depth.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR; // 0: reverse-Z far, every layer passes GREATER
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {size, size}};
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(colors.size());
    info.pColorAttachments = colors.data();
    info.pDepthAttachment = t.depth.image ? &depth : nullptr;
    vkCmdBeginRendering(cmd, &info);
}

void toAttachment(VkCommandBuffer cmd, const Image& image, bool depth) {
    if (!image.image) return;
    const VkPipelineStageFlags2 stages = depth ? VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                                     VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT
                                               : VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
    const VkAccessFlags2 access = depth ? VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT
                                        : VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT;
    imageBarrier(cmd, image.image, VK_IMAGE_LAYOUT_UNDEFINED,
                 depth ? VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                 stages, access, stages, access, {image.aspect, 0, 1, 0, 1});
}

void recordDraw(VkCommandBuffer cmd, Rig& rig, const Bench& b, VkPipeline pipeline, const Targets& t) {
    for (const Image& image : t.colors)
        toAttachment(cmd, image, false);
    toAttachment(cmd, t.depth, true);
    beginRendering(cmd, t, b.draw.size);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, rig.layout, 1, 1, &rig.set.set, 0, nullptr);
    setViewportAndScissor(cmd, b.draw.size, b.draw.size);
    vkCmdSetCullMode(cmd, b.draw.cullAll ? VK_CULL_MODE_FRONT_AND_BACK : VK_CULL_MODE_NONE);
    vkCmdPushConstants(cmd, rig.layout, kPushStages, 0, sizeof(CalPush), &b.push);
    if (b.draw.indirectDraws > 0) {
        // The context enables multiDrawIndirect with drawIndirectCount (context.cpp); without it a
        // call draws one. At most maxDrawIndirectCount a call (65,535 at the least).
        const uint32_t perCall = rig.ctx.caps.drawIndirectCount
                                     ? std::max(rig.ctx.properties.limits.maxDrawIndirectCount, 1u)
                                     : 1u;
        for (uint32_t first = 0; first < b.draw.indirectDraws; first += perCall)
            vkCmdDrawIndirect(cmd, t.indirect.buffer, first * sizeof(VkDrawIndirectCommand),
                              std::min(perCall, b.draw.indirectDraws - first),
                              sizeof(VkDrawIndirectCommand));
    } else if (b.indexed()) {
        vkCmdBindIndexBuffer(cmd, t.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, b.vertexCount(), b.instanceCount(), 0, 0, 0);
    } else {
        vkCmdDraw(cmd, b.vertexCount(), b.instanceCount(), 0, 0);
    }
    vkCmdEndRendering(cmd);
}

} // namespace

Rig::Rig(GpuContext& c, uint64_t bytes) : ctx(c) {
    const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    src = createBuffer(ctx, bytes, usage, MemoryKind::Device, {"calibrate", "calibrate", "source", "what the reads read (zeros)"});
    dst = createBuffer(ctx, bytes, usage, MemoryKind::Device,
                       {"calibrate", "calibrate", "destination", "what the writes and atomics write"});
    texture = createImage(ctx, {kTextureFormat, TP_CAL_TEXTURE_SIZE, TP_CAL_TEXTURE_SIZE, 1, VK_SAMPLE_COUNT_1_BIT,
                                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT},
                          {"calibrate", "calibrate", "texture", "what the texture fetches read"});
    depthMsaa4 = createImage(ctx, {VK_FORMAT_D32_SFLOAT, TP_CAL_TEXTURE_SIZE, TP_CAL_TEXTURE_SIZE, 1,
                                   VK_SAMPLE_COUNT_4_BIT,
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT},
                             {"calibrate", "calibrate", "depth_msaa4", "what image_read_msaa4 reads"});
    sampler = createRepeatSampler(ctx, VK_FILTER_LINEAR);
    nearest = createRepeatSampler(ctx, VK_FILTER_NEAREST);
    const std::vector<SetBinding> bindings = {{TP_CAL_BINDING_SRC, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                              {TP_CAL_BINDING_DST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                              {TP_CAL_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                              {TP_CAL_BINDING_DEPTH_MSAA4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}};
    set = createPassSet(ctx, bindings);
    set.pass = "calibrate";
    set.bindings = bindings; // what reflection checks each kind's shader against
    writeBufferDescriptor(ctx, set.set, TP_CAL_BINDING_SRC, src.buffer);
    writeBufferDescriptor(ctx, set.set, TP_CAL_BINDING_DST, dst.buffer);
    writeImageDescriptor(ctx, set.set, TP_CAL_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                         texture.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sampler);
    writeImageDescriptor(ctx, set.set, TP_CAL_BINDING_DEPTH_MSAA4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                         depthMsaa4.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, nearest);
    createLayout(*this);
    fill(ctx, *this);
}

Rig::~Rig() {
    vkDestroyPipelineLayout(ctx.device, layout, nullptr);
    vkDestroyDescriptorSetLayout(ctx.device, emptySet, nullptr);
    destroyPassSet(ctx, set);
    vkDestroySampler(ctx.device, sampler, nullptr);
    vkDestroySampler(ctx.device, nearest, nullptr);
}

Targets createTargets(GpuContext& ctx, const Bench& b) {
    Targets t;
    if (!b.graphics) return t;
    const BenchDraw& d = b.draw;
    for (VkFormat f : colorFormats(d))
        t.colors.push_back(createImage(ctx, {f, d.size, d.size, 1, d.samples, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT},
                                       {"calibrate", "calibrate", "colour", "the raster ceilings' colour attachment"}));
    if (d.depth)
        t.depth = createImage(ctx, {VK_FORMAT_D32_SFLOAT, d.size, d.size, 1, d.samples,
                                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT},
                              {"calibrate", "calibrate", "depth", "the raster ceilings' depth attachment"});
    if (d.indirectDraws > 0) {
        const std::vector<VkDrawIndirectCommand> commands(d.indirectDraws, {3u, 1u, 0u, 0u});
        t.indirect = createBufferWithData(
            ctx, commands.data(), commands.size() * sizeof(VkDrawIndirectCommand),
            VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
            {"calibrate", "calibrate", "draw_commands", "draw_culled's indirect draws"});
    }
    if (b.indexed()) {
        const std::vector<uint32_t> indices = gridIndices(b.push.stride);
        t.indices = createBufferWithData(
            ctx, indices.data(), indices.size() * sizeof(uint32_t),
            VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
            {"calibrate", "calibrate", "grid_indices", "the indexed grid's triangles"});
    }
    return t;
}

VkPipeline createBenchPipeline(Rig& rig, const Bench& b) {
    if (!b.graphics)
        return createComputePipeline(rig.ctx, "calibrate_" + std::to_string(b.kind) + "_comp", {}, rig.layout, &rig.set);
    GraphicsPipelineDesc d;
    d.vertexShader = "calibrate_v" + std::to_string(b.draw.vertex) + "_vert";
    d.fragmentShader = b.draw.fragment ? "calibrate_" + std::to_string(b.kind) + "_frag" : "";
    d.colorFormats = colorFormats(b.draw);
    d.depthFormat = b.draw.depth ? VK_FORMAT_D32_SFLOAT : VK_FORMAT_UNDEFINED;
    d.depthTest = d.depthWrite = b.draw.depth;
    d.samples = b.draw.samples;
    d.blend = b.draw.blend;
    d.layout = rig.layout;
    // Every fragment kind declares the texture (calibrate_texture.glsl) and no buffer; the
    // depth-only draw declares nothing. What reflection checks the shaders against:
    PassSet drawSet = rig.set;
    drawSet.bindings = {{TP_CAL_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}};
    d.passSet = b.draw.fragment ? &drawSet : nullptr;
    return createGraphicsPipeline(rig.ctx, d);
}

void recordBench(VkCommandBuffer cmd, Rig& rig, const Bench& b, VkPipeline pipeline, const Targets& targets) {
    if (b.graphics) return recordDraw(cmd, rig, b, pipeline, targets);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, rig.layout, 1, 1, &rig.set.set, 0, nullptr);
    vkCmdPushConstants(cmd, rig.layout, kPushStages, 0, sizeof(CalPush), &b.push);
    vkCmdDispatch(cmd, b.invocations / TP_CAL_GROUP_SIZE, 1, 1);
}

} // namespace tp::calibrate
