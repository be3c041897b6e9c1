#pragma once
// The light passes' count of the fragments that evaluate their light (light.frag under
// TP_MP_LIGHT_PASS; docs/multipass_forward.md, "Quads beyond a light's range"): a 2x2 quad
// beyond the light's range adds its zero without the light or the material, so the fragments
// no longer count either. On a GPU with pass statistics the shader's `_count` variants add each
// subgroup's evaluating fragments into the buffer "light_pass_lit" (TP_MP_LIT_SLOTS words,
// zeroed by "light_pass_lit_clear", summed after the frame); elsewhere nothing is counted and
// the renderer's stats say why.
#include <vector>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/renderer/renderer.h"
#include "multipass_forward/passes.h"

namespace tp::mp {

class LightCount {
  public:
    // enabled: pass statistics on; a CPU device, or one without the fragment stage's subgroup
    // reductions, counts nothing (lavapipe cannot compile the helper test, and the count
    // variants' storage buffer alone slowed its light passes).
    LightCount(GpuContext& ctx, const SceneGpu& scene, bool passStatistics);
    ~LightCount();
    LightCount(const LightCount&) = delete;
    LightCount& operator=(const LightCount&) = delete;

    // Before the light passes: the buffer, its clear and the light passes' use of it.
    void plan(FrameGraph& graph, std::vector<PassUse>& lightPassUses);
    // The light passes' environment: the counting set between the scene and shadow sets in its
    // layout, or `env` as it is when nothing is counted. After the graph's compile.
    PassEnv prepare(FrameGraph& graph, const PassEnv& env, VkDescriptorSetLayout shadowSet);
    const PassSet* set() const { return buffer_.valid() ? &set_ : nullptr; }
    void collect(FrameGraph& graph);
    // light_passes' light work and material fetches (the count), or why they are left out.
    void addWork(RendererStats& s, bool hasLights) const;

  private:
    GpuContext& ctx_;
    const SceneGpu& scene_;
    const bool enabled_;
    ResourceHandle buffer_;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE; // scene, counting and shadow sets
    double fragments_ = -1;                    // the last frame's count; -1: none yet
};

} // namespace tp::mp
