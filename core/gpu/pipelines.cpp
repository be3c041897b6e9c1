#include "core/gpu/pipelines.h"

#include <stdexcept>

#include "core/gpu/context.h"
#include "core/gpu/embedded_shaders.h"
#include "core/gpu/shader_reflection.h"
#include "core/gpu/vk_check.h"

namespace tp {
namespace {

struct SpecData {
    std::vector<VkSpecializationMapEntry> entries;
    std::vector<uint32_t> values;
    VkSpecializationInfo info{};
};

void fillSpec(SpecData& s, const std::vector<SpecConstant>& constants) {
    for (const SpecConstant& c : constants) {
        s.entries.push_back({c.id, uint32_t(s.values.size() * 4), 4});
        s.values.push_back(c.value);
    }
    s.info.mapEntryCount = uint32_t(s.entries.size());
    s.info.pMapEntries = s.entries.data();
    s.info.dataSize = s.values.size() * 4;
    s.info.pData = s.values.data();
}

VkPipelineColorBlendAttachmentState blendState(BlendMode mode) {
    VkPipelineColorBlendAttachmentState a{};
    a.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                       VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    if (mode == BlendMode::None) return a;
    a.blendEnable = VK_TRUE;
    a.colorBlendOp = VK_BLEND_OP_ADD;
    a.alphaBlendOp = VK_BLEND_OP_ADD;
    if (mode == BlendMode::Alpha) {
        a.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        a.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        // Keep destination alpha (1 for the opaque background): hdr alpha is not coverage.
        a.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        a.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    } else {
        a.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
        a.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
        a.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
        a.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    }
    return a;
}

} // namespace

VkShaderModule createShaderModule(GpuContext& ctx, const std::string& name) {
    for (const EmbeddedShader& s : embeddedShaders()) {
        if (name != s.name) continue;
        VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        info.codeSize = size_t(s.wordCount) * 4;
        info.pCode = s.words;
        VkShaderModule module;
        VK_CHECK(vkCreateShaderModule(ctx.device, &info, nullptr, &module));
        return module;
    }
    throw std::logic_error("no embedded shader named " + name);
}

namespace {

// The fixed-function state every scene pipeline shares, filled from its description: triangle
// lists, back faces culled unless a draw says double-sided (dynamic cull mode), dynamic
// viewport and scissor, dynamic rendering. Its create infos point into itself: not copyable.
struct FixedState {
    explicit FixedState(const GraphicsPipelineDesc& d);
    FixedState(const FixedState&) = delete;
    FixedState& operator=(const FixedState&) = delete;
    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    VkPipelineViewportStateCreateInfo viewport{
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    VkPipelineRasterizationStateCreateInfo raster{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    VkPipelineMultisampleStateCreateInfo ms{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    VkPipelineDepthStencilStateCreateInfo depth{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    std::vector<VkPipelineColorBlendAttachmentState> blends;
    VkPipelineColorBlendStateCreateInfo blend{
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    VkDynamicState dynamics[4] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                  VK_DYNAMIC_STATE_CULL_MODE, VK_DYNAMIC_STATE_STENCIL_REFERENCE};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
};

FixedState::FixedState(const GraphicsPipelineDesc& d)
    : blends(d.colorFormats.size(),
             d.blend == BlendMode::Custom ? d.customBlend : blendState(d.blend)) {
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_BACK_BIT;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    ms.rasterizationSamples = d.samples;
    ms.sampleShadingEnable = d.sampleShading ? VK_TRUE : VK_FALSE;
    ms.minSampleShading = 1.0f;
    depth.depthTestEnable = d.depthTest;
    depth.depthWriteEnable = d.depthWrite;
    depth.depthCompareOp = d.depthCompare;
    if (d.stencilOnce) {
        depth.stencilTestEnable = VK_TRUE;
        depth.front = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_REPLACE, VK_STENCIL_OP_KEEP,
                       VK_COMPARE_OP_NOT_EQUAL, 0xff, 0xff, 0};
        depth.back = depth.front;
    }
    blend.attachmentCount = uint32_t(blends.size());
    blend.pAttachments = blends.data();
    dynamic.dynamicStateCount = d.stencilOnce ? 4 : 3;
    dynamic.pDynamicStates = dynamics;
    rendering.colorAttachmentCount = uint32_t(d.colorFormats.size());
    rendering.pColorAttachmentFormats = d.colorFormats.data();
    rendering.depthAttachmentFormat = d.depthFormat;
    if (d.stencilOnce) rendering.stencilAttachmentFormat = d.depthFormat;
}

} // namespace

VkPipeline createGraphicsPipeline(GpuContext& ctx, const GraphicsPipelineDesc& d) {
    std::vector<std::string> shaders = {d.vertexShader};
    if (!d.fragmentShader.empty()) shaders.push_back(d.fragmentShader);
    checkPassBindings(d.passSet, shaders);
    SpecData spec;
    fillSpec(spec, d.specConstants);
    std::vector<VkShaderModule> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    auto addStage = [&](VkShaderStageFlagBits stage, const std::string& name) {
        modules.push_back(createShaderModule(ctx, name));
        VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        s.stage = stage;
        s.module = modules.back();
        s.pName = "main";
        s.pSpecializationInfo = &spec.info;
        stages.push_back(s);
    };
    addStage(VK_SHADER_STAGE_VERTEX_BIT, d.vertexShader);
    if (!d.fragmentShader.empty()) addStage(VK_SHADER_STAGE_FRAGMENT_BIT, d.fragmentShader);

    FixedState f(d);
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                      &f.rendering};
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &f.vertexInput;
    info.pInputAssemblyState = &f.assembly;
    info.pViewportState = &f.viewport;
    info.pRasterizationState = &f.raster;
    info.pMultisampleState = &f.ms;
    info.pDepthStencilState = &f.depth;
    info.pColorBlendState = &f.blend;
    info.pDynamicState = &f.dynamic;
    info.layout = d.layout;
    VkPipeline pipeline;
    VkResult r =
        vkCreateGraphicsPipelines(ctx.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    for (VkShaderModule m : modules)
        vkDestroyShaderModule(ctx.device, m, nullptr);
    VK_CHECK(r);
    return pipeline;
}

VkPipeline createComputePipeline(GpuContext& ctx, const std::string& shader,
                                 const std::vector<SpecConstant>& specConstants,
                                 VkPipelineLayout layout, const PassSet* passSet,
                                 uint32_t fullSubgroups) {
    checkPassBindings(passSet, {shader});
    SpecData spec;
    fillSpec(spec, specConstants);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = createShaderModule(ctx, shader);
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = &spec.info;
    VkPipelineShaderStageRequiredSubgroupSizeCreateInfo required{
        VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_REQUIRED_SUBGROUP_SIZE_CREATE_INFO};
    if (fullSubgroups > 0) {
        if (!ctx.caps.computeFullSubgroups || fullSubgroups != ctx.caps.subgroupSize)
            throw std::runtime_error("compute shader " + shader + " needs full subgroups of " +
                                     std::to_string(fullSubgroups) +
                                     " lanes, which the device cannot guarantee");
        required.requiredSubgroupSize = fullSubgroups;
        info.stage.pNext = &required;
        info.stage.flags = VK_PIPELINE_SHADER_STAGE_CREATE_REQUIRE_FULL_SUBGROUPS_BIT;
    }
    info.layout = layout;
    VkPipeline pipeline;
    VkResult r = vkCreateComputePipelines(ctx.device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    vkDestroyShaderModule(ctx.device, info.stage.module, nullptr);
    VK_CHECK(r);
    return pipeline;
}

void setViewportAndScissor(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
    VkViewport vp{0.0f, float(height), float(width), -float(height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {width, height}};
    vkCmdSetViewport(cmd, 0, 1, &vp);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

VkPipelineLayout createPassPipelineLayout(GpuContext& ctx, VkDescriptorSetLayout emptySet,
                                          VkDescriptorSetLayout passSet,
                                          VkShaderStageFlags pushStages, uint32_t pushBytes) {
    const VkDescriptorSetLayout sets[] = {emptySet, passSet};
    VkPushConstantRange range{pushStages, 0, pushBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 2;
    info.pSetLayouts = sets;
    info.pushConstantRangeCount = pushBytes ? 1 : 0; // none: no range (its size must not be 0)
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout;
    VK_CHECK(vkCreatePipelineLayout(ctx.device, &info, nullptr, &layout));
    return layout;
}

} // namespace tp
