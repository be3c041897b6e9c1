#pragma once
// The shadow maps of the pass library (docs/shadows.md): renders the faces SceneGpu's shadow
// plan holds (core/gpuscene/shadow_plan.h) and binds them for sampling as set TP_SET_SHADOW
// (include/shadow_sample.glsl). Two residencies, the trade a pipeline makes:
//
//   Atlas     every shadowed light's faces resident at once, rendered by one pass
//             ("shadow_maps") before the shading: what tiled and clustered shading need, since
//             any pixel may read any light (Forward+, tiled deferred, the visibility buffer).
//             With --shadow-cache on (the default) the atlas is not a frame pass: it is rendered
//             once, outside the frames, into an image the module keeps (the ledger lists it under
//             the pipeline), and again only when a shadowed light moves (updateView: stale());
//             its one-time GPU time is the counter shadow_maps_render_ms. Off: the pass renders
//             it in every frame.
//   PerLight  one light's map ("shadow_map", the largest light's 3 x 2 block of faces),
//             rendered inside the consuming pass right before that light is shaded and rendered
//             over for the next: what a pipeline that shades one light at a time can do
//             (deferred's light volumes, multipass forward). Memory for one light, a render per
//             light per frame.
//
// A consuming pipeline: plan() in its plan, declares `map()` as Sampled (Atlas) or as its
// pass's DepthAttachment (PerLight) in the passes that read it, prepare() after compile, lays
// out its pipelines with setLayout() as set 2 and specConstant(), bind()s the set before
// shading. PerLight: recordLight() between renderings, then endLight() after shading with it.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "include/shadows.h"

namespace tp {

class GpuContext;
class SceneGpu;
struct DrawItem;

class ShadowMaps {
  public:
    enum class Residency { Atlas, PerLight };

    ShadowMaps(GpuContext& ctx, SceneGpu& scene, Residency residency);
    ~ShadowMaps();
    ShadowMaps(const ShadowMaps&) = delete;
    ShadowMaps& operator=(const ShadowMaps&) = delete;

    // Whether the scene's plan shadows any light (false: plan() adds nothing, and a pipeline
    // builds exactly what it built before shadows existed).
    bool enabled() const;
    // Atlas: the "shadow_atlas" image and the "shadow_maps" pass (cached: neither; the module's
    // own image); PerLight: the "shadow_map" image only. Returns the graph's map (invalid when
    // cached). Remembers the plan's generation (stale()).
    ResourceHandle plan(FrameGraph& graph);
    ResourceHandle map() const { return map_; }
    bool cached() const;
    // Pipelines and the set (after graph.compile()).
    void prepare(FrameGraph& graph);
    VkDescriptorSetLayout setLayout() const { return set_.layout; }
    SpecConstant specConstant() const; // TP_SPEC_SHADOW_LOCAL for this residency
    // A consumer's shading pipeline: the shader's shadowed twin ("x_frag" -> "x_shadow_frag",
    // cmake's triptych_add_shadowed_shader) and the constant, when enabled(); else untouched.
    void apply(std::string& shader, std::vector<SpecConstant>& spec) const;
    // What a pass that samples the atlas declares (Atlas only): nothing when not enabled() or
    // cached (the kept image is outside the graph, readable before any frame starts).
    std::vector<PassUse> sampledUses() const;
    // Binds the set (nothing when not enabled()).
    void bind(VkCommandBuffer cmd, VkPipelineLayout layout, VkPipelineBindPoint point) const;
    // For Renderer::updateView: true when the plan changed its layout (other lights, other
    // sizes) since plan(): plan again. Cached: re-renders the kept atlas when a shadowed light
    // moved (or turned), between frames.
    bool stale();

    // PerLight, inside a pass that declared map() as its DepthAttachment and has no rendering
    // open: renders light `light`'s faces and leaves the map readable by fragment and compute
    // shaders. endLight() returns it to the attachment layout (before the next light or the
    // end of the pass). A light the plan does not shadow records nothing.
    void recordLight(PassContext& pc, uint32_t light);
    void endLight(PassContext& pc);
    bool shadowed(uint32_t light) const;

    // Counters for a renderer's stats: shadowed lights, faces, map bytes, the draws of one
    // render of every face (shadow_face_draws), whether cached and its one-time render.
    std::vector<std::pair<std::string, double>> counters() const;

  private:
    void recordAtlas(PassContext& pc);
    void renderCached();
    std::vector<gpu::LightGpu> shadowedLights() const; // world space, as rendered
    void recordFaces(VkCommandBuffer cmd, uint32_t firstFace, uint32_t faceCount, bool local);
    void cullFaces(); // faceDraws_ from the plan and the lights as they are now

    GpuContext& ctx_;
    SceneGpu& scene_;
    Residency residency_;
    ResourceHandle map_;
    FrameGraph* graph_ = nullptr;
    Image kept_;                              // the cached atlas
    std::vector<gpu::LightGpu> culledLights_; // the shadowed lights faceDraws_ (and kept_) are for
    // Per face, the draws that may reach it: culled once per plan and again when a shadowed
    // light moves, not at every recording.
    std::vector<std::vector<const DrawItem*>> faceDraws_;
    double faceDrawCount_ = 0;
    double keptRenderMs_ = 0;                 // its last one-time render, GPU time
    uint32_t keptRenders_ = 0;
    uint64_t generation_ = 0;
    PassSet set_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, mask_ = VK_NULL_HANDLE;
};

} // namespace tp
