#include "core/gpu/rendering.h"

#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"

namespace tp {

void beginRendering(PassContext& pc, const std::vector<ColorTarget>& colors,
                    std::optional<DepthTarget> depth) {
    // The attachments are named twice, in the pass's uses and here: a target the pass did
    // not declare would get no barrier and a wrong layout, so it is an error.
    for (const ColorTarget& c : colors) {
        pc.expectUse(c.image, Use::ColorAttachment);
        if (c.resolve.valid()) pc.expectUse(c.resolve, Use::ColorResolve);
    }
    if (depth) {
        pc.expectUse(depth->image, depth->readOnly ? Use::DepthTest : Use::DepthAttachment);
        if (depth->resolve.valid()) pc.expectUse(depth->resolve, Use::DepthResolve);
    }
    std::vector<VkRenderingAttachmentInfo> colorInfos;
    for (const ColorTarget& c : colors) {
        VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = pc.image(c.image).view;
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        a.loadOp = c.clear      ? VK_ATTACHMENT_LOAD_OP_CLEAR
                   : c.dontCare ? VK_ATTACHMENT_LOAD_OP_DONT_CARE
                                : VK_ATTACHMENT_LOAD_OP_LOAD;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.clearValue.color = c.clearValue;
        if (c.resolve.valid()) {
            a.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
            a.resolveImageView = pc.image(c.resolve).view;
            a.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        }
        colorInfos.push_back(a);
    }
    VkRenderingAttachmentInfo depthInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    VkRenderingAttachmentInfo stencilInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    if (depth) {
        depthInfo.imageView = pc.image(depth->image).view;
        const VkFormat format = pc.image(depth->image).desc.format;
        depthInfo.imageLayout =
            depth->readOnly ? VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL
                            : attachmentLayout(format, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
        depthInfo.loadOp = depth->clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        depthInfo.storeOp =
            depth->readOnly ? VK_ATTACHMENT_STORE_OP_NONE : VK_ATTACHMENT_STORE_OP_STORE;
        depthInfo.clearValue.depthStencil = {depth->clearValue, 0};
        if (depth->resolve.valid()) {
            depthInfo.resolveMode = VK_RESOLVE_MODE_SAMPLE_ZERO_BIT;
            depthInfo.resolveImageView = pc.image(depth->resolve).view;
            depthInfo.resolveImageLayout =
                attachmentLayout(format, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
        }
        if (depth->stencil) {
            // No resolve beside it: depth and stencil resolve modes must agree on devices
            // without independentResolveNone, and nothing needs the stencil resolved.
            if (depth->readOnly || depth->resolve.valid() || !hasStencil(format))
                throw GraphError("a stencil attachment needs a writable depth-stencil image, "
                                 "not resolved");
            stencilInfo = depthInfo;
            stencilInfo.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
            stencilInfo.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
            stencilInfo.resolveMode = VK_RESOLVE_MODE_NONE;
            stencilInfo.resolveImageView = VK_NULL_HANDLE;
        }
    }
    const Image& any = colors.empty() ? pc.image(depth->image) : pc.image(colors.front().image);
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {any.desc.width, any.desc.height}};
    info.layerCount = 1;
    info.colorAttachmentCount = uint32_t(colorInfos.size());
    info.pColorAttachments = colorInfos.data();
    info.pDepthAttachment = depth ? &depthInfo : nullptr;
    info.pStencilAttachment = depth && depth->stencil ? &stencilInfo : nullptr;
    vkCmdBeginRendering(pc.cmd, &info);
    setViewportAndScissor(pc.cmd, any.desc.width, any.desc.height);
}

void endRendering(PassContext& pc) {
    vkCmdEndRendering(pc.cmd);
}

} // namespace tp
