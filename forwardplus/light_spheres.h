#pragma once
// Forward+'s light_spheres pass (compute, one invocation per light, before light_culling):
// each light's view-space bounding sphere (lightSphereView), so that the culling reads 16
// bytes per candidate instead of loading and transforming the light once per tile it is a
// candidate of. Buffer light_spheres: 16 bytes per light, in the ledger.
#include <cstdint>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"

namespace tp {

class GpuContext;
class SceneGpu;

namespace fp {

class LightSpheres {
  public:
    LightSpheres(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~LightSpheres();
    // Creates the buffer and the pass; returns the buffer (the culling reads it).
    ResourceHandle plan(FrameGraph& graph);
    void prepare(FrameGraph& graph);

  private:
    void record(PassContext& pc);

    GpuContext& ctx_;
    SceneGpu& scene_;
    uint32_t lightCount_ = 0;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

} // namespace fp
} // namespace tp
