#pragma once
// Forward+'s shading passes: forward_opaque (opaque and masked draws, depth EQUAL against the
// prepass) and, when something blended is drawn, forward_transparent (blended draws back to
// front, depth GREATER, alpha-blended), each fragment walking its tile's light list (its
// cluster's bitmask when clustered). The last of them resolves hdr_msaa into hdr under MSAA.
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/passes/image_clear.h"
#include "core/passes/lights_ubo.h"
#include "core/passes/material_pipelines.h"
#include "core/passes/materials_ubo.h"
#include "core/renderer/msaa_knob.h"
#include "include/shared.h"

namespace tp {
class GpuContext;
class SceneGpu;
} // namespace tp

namespace tp {
class ShadowMaps;
namespace passes {
class MeshletCull;
}
} // namespace tp

namespace tp::fp {

// What the shaders' variant and constants depend on.
struct ShadingConfig {
    Sampling sampling;
    uint32_t tileSize = 16;
    uint32_t layout = 0;   // TP_FP_LAYOUT_*
    uint32_t slices = 16;  // clustered only
    bool twoLists = false; // a separate transparent list per tile
    bool clustered = false;
    bool blendPass = false; // blended draws are drawn: forward_transparent runs
    bool subgroupLoop = false;
    uint32_t tilesX = 1, tilesY = 1; // the tile grid (fp_params' tiles.xy), compiled into the shading
};

// hdr: the single-sample output; hdrMsaa/depthMsaa valid under MSAA only; depth: the
// prepass's single-sample depth at 1x. tiles, indices, masks (clustered): the light lists.
struct ShadingTargets {
    ResourceHandle hdr, hdrMsaa, depth, depthMsaa, tiles, indices, masks;
    VkFormat hdrFormat = VK_FORMAT_UNDEFINED;
    const ShadowMaps* shadows = nullptr; // the atlas, sampled by both passes when enabled
    // --cull-geometry: forward_opaque draws the meshlets this pass kept (the prepass's);
    // forward_transparent draws its meshes whole.
    const passes::MeshletCull* cull = nullptr;
};

class ForwardShading {
  public:
    ForwardShading(GpuContext& ctx, const SceneGpu& scene, ShadingConfig config)
        : ctx_(ctx), scene_(scene), config_(config), pipelines_(ctx), hdrClear_(ctx) {}
    ~ForwardShading();
    ForwardShading(const ForwardShading&) = delete;
    ForwardShading& operator=(const ForwardShading&) = delete;
    void plan(FrameGraph& graph, const ShadingTargets& t);
    // params: fp_params (uploaded outside the graph).
    void prepare(FrameGraph& graph, VkBuffer params);
    // A new view (Renderer::updateView): the lights' uniform-buffer copy again, when the shaders
    // read it (between frames).
    void updateLights();

  private:
    std::vector<PassUse> uses(bool transparent) const;
    void createPassSet(FrameGraph& graph, VkBuffer params);
    GraphicsPipelineDesc pipelineDesc(AlphaMode mode) const;
    void record(PassContext& pc, bool transparent);
    GpuContext& ctx_;
    const SceneGpu& scene_;
    ShadingConfig config_;
    ShadingTargets t_;
    PassSet set_;
    // The lights as a uniform buffer (TP_FP_BINDING_LIGHTS_UBO); active() says whether the
    // shaders read it (TP_FP_SPEC_LIGHTS_UBO) or only bind it.
    std::optional<LightsUbo> lightsUbo_;
    // The materials as a uniform buffer (TP_FP_BINDING_MATERIALS_UBO); active() says whether
    // the shaders read it (TP_FP_SPEC_MATERIALS_UBO) or only bind it.
    std::optional<MaterialsUbo> materialsUbo_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    // Each draw's pipeline: its material's texture indices compiled in (material_pipelines.h).
    MaterialPipelines pipelines_;
    // forward_hdr_clear: the radiance zeroed by compute before forward_opaque, not by its
    // render pass (on the H200 a render pass's clear runs on the graphics SMs, about 55 GB/s).
    ImageClear hdrClear_;
};

} // namespace tp::fp
