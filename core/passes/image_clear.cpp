#include "core/passes/image_clear.h"

#include <cstring>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/gpu/vk_check.h"
#include "include/shared.h"
#include "passes/image_clear.h"

namespace tp {
namespace {

// The storage format qualifier of the shader variant for `format`; null: no variant.
const char* storageFormat(VkFormat format) {
    switch (format) {
    case VK_FORMAT_R32_SFLOAT:
        return "r32f";
    case VK_FORMAT_R32G32B32A32_SFLOAT:
        return "rgba32f";
    case VK_FORMAT_R16G16B16A16_SFLOAT:
        return "rgba16f";
    default:
        return nullptr;
    }
}

bool canStore(GpuContext& ctx, const FrameGraph& graph, VkFormat format, uint32_t samples) {
    if (samples > 1 && !ctx.caps.storageImageMultisample) return false;
    return bool(checkImageSupported(
        ctx, {format, graph.width(), graph.height(), 1, VkSampleCountFlagBits(samples),
              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT}));
}

} // namespace

ImageClear::~ImageClear() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    if (empty_) vkDestroyDescriptorSetLayout(ctx_.device, empty_, nullptr);
    destroyPassSet(ctx_, set_);
}

bool ImageClear::plan(FrameGraph& graph, const std::string& name, ResourceHandle image,
                      VkClearColorValue value) {
    const VkFormat format = graph.format(image.index);
    const uint32_t samples = graph.samples(image.index);
    const char* f = storageFormat(format);
    if ((ctx_.isCpuDevice() && !onCpuDevice_) || !f || !canStore(ctx_, graph, format, samples))
        return false;
    name_ = name;
    shader_ = std::string("image_clear_") + f + (samples > 1 ? "_ms" : "") + "_comp";
    samples_ = samples;
    value_ = value;
    graph.addPass(name, {{image, Use::StorageWrite, TP_IC_BINDING_IMAGE}},
                  [this](PassContext& pc) { record(pc); });
    return true;
}

void ImageClear::prepare(FrameGraph& graph) {
    if (name_.empty()) return;
    set_ = graph.createPassSet(name_);
    VkDescriptorSetLayoutCreateInfo empty{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    VK_CHECK(vkCreateDescriptorSetLayout(ctx_.device, &empty, nullptr, &empty_));
    layout_ = createPassPipelineLayout(ctx_, empty_, set_.layout, 0, 0);
    std::vector<SpecConstant> spec{{TP_IC_SPEC_SAMPLES, samples_}};
    for (uint32_t c = 0; c < 4; ++c) {
        uint32_t bits;
        std::memcpy(&bits, &value_.float32[c], 4);
        spec.push_back({TP_IC_SPEC_VALUE + c, bits});
    }
    pipeline_ = createComputePipeline(ctx_, shader_, spec, layout_, &set_);
}

void ImageClear::record(PassContext& pc) {
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    vkCmdDispatch(pc.cmd, (pc.graph.width() + TP_IC_GROUP - 1) / TP_IC_GROUP,
                  (pc.graph.height() + TP_IC_GROUP - 1) / TP_IC_GROUP, 1);
}

} // namespace tp
