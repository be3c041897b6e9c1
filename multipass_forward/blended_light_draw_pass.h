#pragma once
// Multipass forward's blended draws' light lists on the GPU (pass "blended_light_draws", compute;
// shaders/multipass_forward/blended_light_draws.comp; --light-draws gpu-blended, where the
// device has dual-source blending and no light is shadowed; not the default: the discard costs
// the frame more than the per-view recording it saves, docs/multipass_forward.md). Every frame, per blended draw on
// screen (back to front, the blended pass's order), the lights that touch it by the light plan's
// rule, in light order, each as two indexed indirect draws of the draw's reversed triangles: the
// light's draw and its transmittance reset, which the blended pass draws with one dual-source
// pipeline (light.frag, TP_MP_BLENDED_GPU) in one vkCmdDrawIndexedIndirectCount per blended draw.
// The light's scissor is a discard against its rectangle (the row the shader reads, this pass's
// light table). So no view tests blended draws against lights on the CPU, and the recording no
// longer grows with the lights (docs/multipass_forward.md, "Light lists on the GPU").
//
// Per view the CPU writes O(lights + blended draws): each light's rectangle, sphere and index, and
// each blended draw's rectangle, box and place in the reversed index buffer (update()).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "multipass_forward/light_plan.h"

namespace tp {
class GpuContext;
class SceneGpu;
struct DrawItem;
} // namespace tp

namespace tp::mp {

class BlendedLightDrawPass {
  public:
    // Empty when this device, size or configuration cannot take it: why not (the blended
    // draws' lights are then planned and recorded on the CPU, as --light-draws cpu).
    static std::string unavailable(const GpuContext& ctx, const SceneGpu& scene,
                                   uint32_t localLights, bool shadows, bool additive);
    BlendedLightDrawPass(GpuContext& ctx, const SceneGpu& scene, uint32_t localLights);
    ~BlendedLightDrawPass();
    BlendedLightDrawPass(const BlendedLightDrawPass&) = delete;
    BlendedLightDrawPass& operator=(const BlendedLightDrawPass&) = delete;

    // The pass and its buffers: blended_light_draw_commands, _counts, blended_light_draw_meshes
    // (exported: read after the frame by collect()).
    void plan(FrameGraph& graph);
    // The compute pipeline, and the light table's set (set TP_SET_PASS of the blended light
    // draws' pipeline layout: lightSetLayout()).
    void prepare(FrameGraph& graph);
    VkDescriptorSetLayout lightSetLayout() const { return lightSet_.layout; }
    // A new view (or the first): the lights' rectangles and the blended draws on screen, each
    // with its first index in the reversed index buffer (`reversedFirst`).
    void update(const LightPlan& plan,
                const std::function<uint32_t(const DrawItem*)>& reversedFirst);
    // What the pass that draws them declares.
    std::vector<PassUse> drawUses() const;
    // Blended draw `b`'s light draws and resets (b: its place in plan.blended): one indirect
    // call. The caller binds the pipeline, the light set (bindLightSet), the reversed index
    // buffer, and pushes the draw's DrawPush and cull mode.
    void record(PassContext& pc, uint32_t b) const;
    void bindLightSet(VkCommandBuffer cmd, VkPipelineLayout layout) const;
    // After a frame: per local light, the blended draws it lit (blended_light_draw_meshes).
    void collect(FrameGraph& graph);
    const std::vector<uint32_t>& meshes() const { return meshes_; }

  private:
    void recordPass(PassContext& pc);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    const uint32_t lights_, blendedDraws_; // local lights; blended draws of the scene
    uint32_t onScreen_ = 0;                // blended draws this view
    Buffer params_, lightRows_, drawRows_; // per view, written by the CPU (mapped)
    ResourceHandle commands_, counts_, meshesBuffer_;
    PassSet set_, lightSet_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    std::vector<uint32_t> meshes_;
};

} // namespace tp::mp
