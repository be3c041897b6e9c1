// Shadows the multipass way (--shadows, docs/multipass_forward.md "Shadows"): a map per light
// pass. ShadowMaps' PerLight residency holds one light's faces; a pass that shades a shadowed
// light renders that light's map right before its draws, inside the same graph pass, and
// renders over it for the next shadowed light. Memory: one light's map, whatever the count.
#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/gpu/resources.h"
#include "core/passes/shadow_maps.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

void addShadowUse(std::vector<PassUse>& uses, const ShadowMaps* shadows) {
    if (shadows)
        for (const PassUse& u : shadows->perLightUses()) uses.push_back(u); // map, culled draws
}

VkPipeline createShadowedTwin(const PassEnv& env, GraphicsPipelineDesc d) {
    if (!env.shadows || !env.shadows->enabled()) return VK_NULL_HANDLE;
    env.shadows->apply(d.fragmentShader, d.specConstants);
    return createGraphicsPipeline(env.ctx, d);
}

ShadowedShading::ShadowedShading(PassContext& pc, const Targets& t, bool resolve,
                                 ShadowMaps* shadows, const std::vector<uint32_t>& order,
                                 bool stencil)
    : pc_(pc), t_(t), resolve_(resolve), stencil_(stencil),
      shadows_(shadows && shadows->enabled() ? shadows : nullptr) {
    uint32_t held = ~0u;
    for (uint32_t light : order)
        if (shadowed(light) && light != held) {
            held = light;
            ++switchesLeft_;
        }
    beginShading(pc, t, resolve && switchesLeft_ == 0, false, stencil_);
}

bool ShadowedShading::shadowed(uint32_t light) const {
    return shadows_ && shadows_->shadowed(light);
}

bool ShadowedShading::hold(uint32_t light) {
    if (!shadowed(light) || light == held_) return false;
    endRendering(pc_);
    if (held_ != ~0u) shadows_->endLight(pc_);
    shadows_->recordLight(pc_, light);
    held_ = light;
    ++renders_;
    --switchesLeft_;
    // Two renderings of one pass blend into the same target (and resolve into hdr): the
    // graph orders passes, not renderings within a pass, so this barrier is written by hand.
    memoryBarrier(pc_.cmd, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                  VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    // With the stencil (the light passes), each rendering stores depth and stencil and the next
    // loads depth and clears the stencil: writes ordered likewise, in the fragment tests.
    if (stencil_) {
        constexpr VkPipelineStageFlags2 tests = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                                VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        memoryBarrier(pc_.cmd, tests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, tests,
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                          VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    }
    beginShading(pc_, t_, resolve_ && switchesLeft_ == 0, false, stencil_);
    return true;
}

void ShadowedShading::end() {
    endRendering(pc_);
    if (held_ != ~0u) shadows_->endLight(pc_);
    held_ = ~0u;
}

} // namespace tp::mp
