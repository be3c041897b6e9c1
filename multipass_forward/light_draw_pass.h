#pragma once
// Multipass forward's per-light draw lists on the GPU (pass "light_draws", compute;
// shaders/multipass_forward/light_draws.comp, --light-draws gpu, the default): every frame, each
// local light's opaque and masked draws are selected by the light plan's own rules (screen
// rectangles overlap; at 1x the sphere reaches the box) and written as indexed indirect draws
// into a region of its own (up to 16 commands per draw of the scene, in draw order, compacted
// per run of one cull mode), with a count per run: a draw's commands are the runs of its
// meshlets that the light's sphere reaches (light_draws.comp), over the scene's meshlet index
// buffer. The light passes then record, per light, its scissor and one
// vkCmdDrawIndexedIndirectCount per run: the recording no longer depends on which draws a light
// touches, and no view builds per-light lists on the CPU.
//
// Per view the CPU writes only what is O(lights + draws): each light's scissor (which the
// recording needs anyway: a scissor cannot come from an indirect command) and each draw's screen
// rectangle and camera-relative box (update()). Each command's firstInstance is its material
// (scene_material_vert), so one call draws meshes of many materials.
#include <cstdint>
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

// Each local light's row (rectangle, camera-relative sphere, flags, scene index) in light order,
// for the light-draws passes (this one and blended_light_draw_pass.h): `rows` holds `lights`.
void writeLightRows(const SceneGpu& scene, const LightPlan& plan, uint32_t lights, void* rows);

class LightDrawPass {
  public:
    // Empty when this device or size cannot take it: why not (the renderer then builds the
    // lists on the CPU, as --light-draws cpu, and says so in left_out).
    static std::string unavailable(const GpuContext& ctx, const SceneGpu& scene,
                                   uint32_t localLights);
    // Builds the scene's meshlets if nobody has: the commands draw runs of them. meshletReach:
    // only the meshlets each light reaches (every shaded point on its triangle: 1x, or MSAA at
    // sample rate), else those whose fragments can fall in its scissor.
    LightDrawPass(GpuContext& ctx, SceneGpu& scene, uint32_t localLights, bool meshletReach);
    ~LightDrawPass();
    LightDrawPass(const LightDrawPass&) = delete;
    LightDrawPass& operator=(const LightDrawPass&) = delete;

    // The pass and its buffers: light_draw_commands, light_draw_counts, light_draw_meshes
    // (exported: read after the frame by collect()).
    void plan(FrameGraph& graph);
    void prepare(FrameGraph& graph);
    // A new view (or the first): the lights' scissors and the draws' rectangles and boxes.
    void update(const LightPlan& plan);
    // What a pass that records the lights' draws declares.
    std::vector<PassUse> drawUses() const;
    // Light `slot`'s draws: per run its cull mode and one indirect call. The caller binds the
    // pipeline (scene_material_vert), the scene set and the scene's index buffer, and pushes
    // DrawPush with the light. Returns the calls recorded.
    uint32_t record(PassContext& pc, uint32_t slot) const;
    // After a frame: each local light's opaque and masked draws and the triangles its commands
    // draw (light_draw_meshes).
    void collect(FrameGraph& graph);
    bool collected() const { return collected_; }
    const std::vector<uint32_t>& meshes() const { return meshes_; }
    const std::vector<uint32_t>& triangles() const { return triangles_; }
    uint32_t runs() const { return uint32_t(runFirst_.size()); }

  private:
    void recordPass(PassContext& pc);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    const uint32_t lights_;
    const bool meshletReach_;
    std::vector<const DrawItem*> draws_; // opaque then masked, the scene's order
    const uint32_t spans_;               // commands per draw in a light's region
    std::vector<uint32_t> runFirst_;     // per run: its first draw
    std::vector<uint32_t> runSize_;
    std::vector<bool> runDoubleSided_;
    Buffer params_, lightRows_, drawRows_; // per view, written by the CPU (mapped)
    ResourceHandle commands_, counts_, meshesBuffer_;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    std::vector<uint32_t> meshes_, triangles_;
    bool collected_ = false;
};

} // namespace tp::mp
