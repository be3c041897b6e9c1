#pragma once
// Classic deferred lighting (`--deferred-lighting volumes`): a full-screen base pass adds
// ambient + emissive once (and, under MSAA, writes the edge mask and the 1x depth the
// volumes test against), then one draw per light rasterizes the back faces of its bounding
// volume (sphere, cone or full-screen triangle) and adds that light (blend ONE + ONE) into
// hdr. Shading is the tiled pass's code (shaders/deferred/gbuffer_read.glsl). A blended
// scene under MSAA is lit per sample into hdr_msaa, which the hybrid forward pass blends
// into: volume_sample_base writes each sample's ambient + emissive there, and the volumes
// run per sample against the G-buffer's per-sample depth.
//
// --shadows (docs/deferred.md, "Shadows"): the shadowed lights leave volume_lights for a pass
// of their own, volume_shadowed_lights, that holds one light's shadow map at a time
// (ShadowMaps::Residency::PerLight): for each shadowed light it renders that light's faces
// into the map, then draws the light's volume sampling it, and renders the next light's over
// it. One map's memory, a map render per shadowed light; volume_lights is unchanged.
#include <string>
#include <utility>
#include <vector>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/passes/shadow_maps.h"
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
    // cull, raster: --cull-geometry and --shadow-raster, for the shadowed lights' maps
    // (ShadowMaps: compute is refused for one light's map).
    VolumeLighting(GpuContext& ctx, SceneGpu& scene, CullGeometry cull, ShadowRaster raster)
        : ctx_(ctx), scene_(scene),
          shadows_(ctx, scene, ShadowMaps::Residency::PerLight, cull, raster) {}
    ~VolumeLighting();
    void plan(FrameGraph& graph, DeferredTargets& t);
    void prepare(FrameGraph& graph);
    // The shadow plan changed its layout (other lights, other map sizes): plan again.
    bool stale() { return shadows_.stale(); }
    // Planned with shadows: the volume_shadowed_lights pass exists.
    bool shadowPass() const { return shadows_.map().valid(); }
    // The shadow map's counters for the renderer's stats (none without --shadows).
    std::vector<std::pair<std::string, double>> shadowCounters() const { return shadows_.counters(); }
    void collectShadows(FrameGraph& graph) { shadows_.collect(graph); } // after the frames

  private:
    struct Stage {
        PassSet set;
        VkPipelineLayout layout = VK_NULL_HANDLE;
        VkPipeline pipeline = VK_NULL_HANDLE;
    };
    void prepareBase(FrameGraph& graph);
    void prepareLights(FrameGraph& graph);
    void prepareSampleBase(FrameGraph& graph);
    GraphicsPipelineDesc lightsDesc(const Stage& stage) const;
    void bind(VkCommandBuffer cmd, const Stage& stage);
    void recordBase(PassContext& pc);
    void beginLights(PassContext& pc);
    void drawVolume(VkCommandBuffer cmd, uint32_t light);
    void recordLights(PassContext& pc);
    void recordShadowedLights(PassContext& pc);
    void recordSampleBase(PassContext& pc);
    // A blended scene under MSAA: lit per sample into hdr_msaa (the forward pass blends there).
    bool perSampleHdr() const { return t_->hdrMsaa.valid(); }
    GpuContext& ctx_;
    SceneGpu& scene_;
    const DeferredTargets* t_ = nullptr;
    VkSampler sampler_ = VK_NULL_HANDLE;
    Stage base_, lights_, sampleBase_, shadowed_;
    ShadowMaps shadows_; // one light's map (PerLight), with --shadows
};

} // namespace tp
