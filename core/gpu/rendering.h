#pragma once
// Dynamic rendering begin/end from frame-graph resources, so passes never spell out
// VkRenderingAttachmentInfo by hand. Layouts match the graph's Use (ColorAttachment ->
// COLOR_ATTACHMENT_OPTIMAL, DepthAttachment -> DEPTH_ATTACHMENT_OPTIMAL, DepthTest ->
// READ_ONLY_OPTIMAL; a depth-stencil image: DEPTH_STENCIL_ATTACHMENT_OPTIMAL).
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/frame_graph.h"

namespace tp {

struct ColorTarget {
    ResourceHandle image;
    ResourceHandle resolve; // invalid = none; else averaged into it at the end of the pass
    bool clear = true;      // false = load
    VkClearColorValue clearValue{{0.0f, 0.0f, 0.0f, 1.0f}};
    // Neither cleared nor loaded (with clear false): no sample the pass leaves unwritten is
    // read later. A clear is not free: on the H200 its few graphics SMs clear about 55 GB/s.
    bool dontCare = false;
};

struct DepthTarget {
    ResourceHandle image;
    ResourceHandle resolve;  // invalid = none; else sample 0 is copied into it
    bool clear = true;       // false = load
    bool readOnly = false;   // DepthTest use (no writes)
    float clearValue = 0.0f; // reverse-Z: 0 is the far plane
    // The image's stencil aspect as the stencil attachment too, cleared to 0 at the start and
    // not stored (a depth-stencil format; the pass's pipelines name it as stencil format).
    bool stencil = false;
};

void beginRendering(PassContext& pc, const std::vector<ColorTarget>& colors,
                    std::optional<DepthTarget> depth);
void endRendering(PassContext& pc);

} // namespace tp
