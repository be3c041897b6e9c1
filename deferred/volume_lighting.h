#pragma once
// Classic deferred lighting (`--deferred-lighting volumes`): a full-screen base pass adds
// ambient + emissive once (and, under MSAA, writes the edge mask and the 1x depth the
// volumes test against), then one draw per light rasterizes the back faces of its bounding
// volume (sphere, cone or full-screen triangle) and adds that light (blend ONE + ONE) into
// hdr. Shading is the tiled pass's code (shaders/deferred/gbuffer_read.glsl). A blended
// scene under MSAA is lit per sample into hdr_msaa, which the hybrid forward pass blends
// into: volume_sample_base writes each sample's ambient + emissive there, and the volumes
// run per sample against the G-buffer's per-sample depth.
#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "deferred/deferred_shared.h"
#include "deferred/deferred_targets.h"

namespace tp {

class GpuContext;
class SceneGpu;

// Factor that makes the UV sphere of volumeSphereVertex circumscribe the unit sphere: the
// inverse of the smallest distance from the centre to the plane of a (non-degenerate)
// triangle, with a 1e-3 relative margin for the GPU's sin/cos.
float circumscribedSphereScale();
// Whether a light is drawn with the cone mesh (a spot whose outer half-angle is <= 60
// degrees; wider spots use the sphere, as their cone would be larger than it).
bool drawsCone(const gpu::LightGpu& light);

class VolumeLighting {
  public:
    VolumeLighting(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~VolumeLighting();
    void plan(FrameGraph& graph, DeferredTargets& t);
    void prepare(FrameGraph& graph);

  private:
    struct Stage {
        PassSet set;
        VkPipelineLayout layout = VK_NULL_HANDLE;
        VkPipeline pipeline = VK_NULL_HANDLE;
    };
    void prepareBase(FrameGraph& graph);
    void prepareLights(FrameGraph& graph);
    void prepareSampleBase(FrameGraph& graph);
    void bind(VkCommandBuffer cmd, const Stage& stage);
    void recordBase(PassContext& pc);
    void recordLights(PassContext& pc);
    void recordSampleBase(PassContext& pc);
    // A blended scene under MSAA: lit per sample into hdr_msaa (the forward pass blends there).
    bool perSampleHdr() const { return t_->hdrMsaa.valid(); }
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DeferredTargets* t_ = nullptr;
    VkSampler sampler_ = VK_NULL_HANDLE;
    Stage base_, lights_, sampleBase_;
};

} // namespace tp
