#pragma once
// Shader modules from the embedded SPIR-V, and graphics/compute pipeline creation from a
// small description. All scene draws use dynamic rendering, a negative-height viewport
// (so glTF's counter-clockwise front faces and +Y up hold as in OpenGL), reverse-Z depth
// and dynamic cull mode (double-sided materials are a per-draw switch). Creation throws
// BindingMismatch when a shader and the pass set in the layout disagree.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace tp {

class GpuContext;
struct PassSet;

VkShaderModule createShaderModule(GpuContext& ctx, const std::string& name);

struct SpecConstant {
    uint32_t id;
    uint32_t value; // bools as 0/1
};

enum class BlendMode { None, Alpha, Additive, Custom }; // Custom: GraphicsPipelineDesc::customBlend

struct GraphicsPipelineDesc {
    std::string vertexShader = "scene_vert";
    std::string fragmentShader; // empty: depth-only
    std::vector<SpecConstant> specConstants;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool sampleShading = false; // run the fragment shader per sample
    bool depthTest = true;
    bool depthWrite = true;
    VkCompareOp depthCompare = VK_COMPARE_OP_GREATER; // reverse-Z
    // `depthFormat`'s stencil as a "once per sample" mark: a fragment passes where the stencil
    // is not yet the reference (dynamic state, vkCmdSetStencilReference) and, passing depth
    // too, writes it, so coincident surfaces that all pass depth EQUAL count once per
    // reference (multipass forward's light passes). The rendering names the stencil attachment.
    bool stencilOnce = false;
    BlendMode blend = BlendMode::None;
    // Used as given with BlendMode::Custom (multipass forward's transmittance passes need
    // factors and write masks the named modes do not have).
    VkPipelineColorBlendAttachmentState customBlend{};
    VkPipelineLayout layout = VK_NULL_HANDLE;
    // The pass set in `layout` (null: none). The shaders' set-TP_SET_PASS bindings are
    // checked against it by reflection (core/gpu/shader_reflection.h).
    const PassSet* passSet = nullptr;
};

VkPipeline createGraphicsPipeline(GpuContext& ctx, const GraphicsPipelineDesc& desc);
// fullSubgroups > 0: the workgroups are made of full subgroups of exactly that many lanes
// (it must be ctx.caps.subgroupSize, with ctx.caps.computeFullSubgroups): a shader whose
// workgroup is that size is then one subgroup.
VkPipeline createComputePipeline(GpuContext& ctx, const std::string& shader,
                                 const std::vector<SpecConstant>& specConstants,
                                 VkPipelineLayout layout, const PassSet* passSet = nullptr,
                                 uint32_t fullSubgroups = 0);

// A layout for a pipeline outside the scene's sets (calibrate, the viewer's composite): set 0
// `emptySet` (an empty set layout, so the pass set sits at TP_SET_PASS as in every shader), set 1
// `passSet`, and one push-constant range of `pushBytes` for `pushStages` (none if 0).
VkPipelineLayout createPassPipelineLayout(GpuContext& ctx, VkDescriptorSetLayout emptySet,
                                          VkDescriptorSetLayout passSet,
                                          VkShaderStageFlags pushStages, uint32_t pushBytes);

// Viewport (negative height, depth 0..1) and scissor covering width x height.
void setViewportAndScissor(VkCommandBuffer cmd, uint32_t width, uint32_t height);

} // namespace tp
