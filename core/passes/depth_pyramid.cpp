#include "core/passes/depth_pyramid.h"

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/gpu/stand_ins.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "passes/depth_pyramid.h"

namespace tp::passes {

DepthPyramid::DepthPyramid(GpuContext& ctx, const SceneGpu& scene) : ctx_(ctx), scene_(scene) {}

DepthPyramid::~DepthPyramid() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    if (sampler_) vkDestroySampler(ctx_.device, sampler_, nullptr);
    if (depthView_) vkDestroyImageView(ctx_.device, depthView_, nullptr);
    destroyPassSet(ctx_, set_);
}

ResourceHandle DepthPyramid::plan(FrameGraph& graph, ResourceHandle depth) {
    depth_ = depth;
    width_ = graph.width();
    height_ = graph.height();
    samples_ = uint32_t(graph.samples(depth.index));
    levels_ = gpu::pyramidLevels(width_, height_);
    const VkDeviceSize texels = gpu::pyramidLevelOffset(width_, height_, levels_);
    pyramid_ = graph.createBuffer("depth_pyramid", texels * sizeof(float),
                                  "every level of the depth pyramid: per texel the farthest "
                                  "depth of the pixels it covers (occlusion culling)");
    graph.addPass("depth_pyramid",
                  {{depth, Use::Sampled, TP_DP_BINDING_DEPTH},
                   {pyramid_, Use::StorageWrite, TP_DP_BINDING_PYRAMID}},
                  [this](PassContext& pc) { record(pc); });
    return pyramid_;
}

void DepthPyramid::prepare(FrameGraph& graph) {
    sampler_ = createNearestClampSampler(ctx_); // texelFetch only: the sampler is never used
    // The set is written here, not by FrameGraph::createPassSet, for one case: a depth-stencil
    // image (multipass forward's light passes use the stencil) is sampled through a view of its
    // depth aspect alone, since a descriptor may not name both aspects. Its bindings are the
    // ones the pass's uses declare.
    const Image& depth = graph.image(depth_);
    VkImageView view = depth.view;
    if (depth.aspect & VK_IMAGE_ASPECT_STENCIL_BIT) {
        VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        info.image = depth.image;
        info.viewType = VK_IMAGE_VIEW_TYPE_2D;
        info.format = depth.desc.format;
        info.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
        VK_CHECK(vkCreateImageView(ctx_.device, &info, nullptr, &depthView_));
        view = depthView_;
    }
    const std::vector<SetBinding> bindings = {
        {TP_DP_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {TP_DP_BINDING_PYRAMID, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    set_ = createPassSet(ctx_, bindings);
    set_.pass = "depth_pyramid";
    set_.bindings = bindings;
    writeImageDescriptor(ctx_, set_.set, TP_DP_BINDING_DEPTH,
                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, view,
                         useInfo(Use::Sampled).layout, sampler_);
    writeBufferDescriptor(ctx_, set_.set, TP_DP_BINDING_PYRAMID, graph.buffer(pyramid_).buffer);
    layout_ = scene_.createPipelineLayout(set_.layout);
    pipeline_ = createComputePipeline(
        ctx_, samples_ > 1 ? "depth_pyramid_msaa_comp" : "depth_pyramid_comp", {}, layout_, &set_);
}

void DepthPyramid::record(PassContext& pc) {
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    for (uint32_t level = 0; level < levels_; ++level) {
        // Each level reads the one below it in the same buffer, which the graph tracks whole:
        // the dispatches are ordered here.
        if (level > 0)
            memoryBarrier(pc.cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        // The scene layout's push range (all stages): never the frame's first dispatch (it
        // follows a geometry pass), so the lavapipe crash of docs/geometry.md does not apply.
        const gpu::DepthPyramidPush push{level, width_, height_, samples_};
        vkCmdPushConstants(pc.cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
        const glm::uvec2 size = gpu::pyramidLevelSize(width_, height_, level);
        vkCmdDispatch(pc.cmd, (size.x + TP_DP_GROUP - 1) / TP_DP_GROUP,
                      (size.y + TP_DP_GROUP - 1) / TP_DP_GROUP, 1);
    }
}

} // namespace tp::passes
