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
// shading. PerLight: recordLight() between renderings, then endLight() after shading with it;
// the passes that call it declare perLightUses().
//
// --cull-geometry frustum|full: the faces' meshlets are culled on the GPU first
// (core/passes/shadow_cull.h: the face's frustum and the light's range), one dispatch for
// every face of a render ("shadow_cull" in the frame before "shadow_maps", or before the
// per-light passes for all their lights; inside the kept atlas's one-time render), and each
// (face, draw) is drawn as an indirect count draw of its kept meshlets. The maps are the same
// wherever a receiver the light reaches reads them, the images bit for bit.
//
// --shadow-raster compute (Atlas only; needs the cull): the faces' depth is rasterized by
// compute shaders from the cull's kept meshlets into a buffer and copied into the same D32
// atlas (core/passes/shadow_raster.h): "shadow_raster_clear", "shadow_raster",
// "shadow_raster_big" and "shadow_maps" (the copy) in the frame, or inside the kept atlas's
// one-time render. The depth is within a few ulps of the hardware's (docs/shadows.md).
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/shadow_raster_knob.h"
#include "include/shadows.h"

namespace tp {

class GpuContext;
class SceneGpu;
class ShadowComputeRaster;
class ShadowCull;
struct DrawItem;

class ShadowMaps {
  public:
    enum class Residency { Atlas, PerLight };

    // cull: the pipeline's --cull-geometry (frustum and full cull the faces' meshlets alike:
    // no occlusion for the maps); raster: its --shadow-raster (compute: plan() throws
    // RendererError, one line, for the PerLight residency or without the cull).
    ShadowMaps(GpuContext& ctx, SceneGpu& scene, Residency residency,
               CullGeometry cull = CullGeometry::None, ShadowRaster raster = ShadowRaster::Hardware);
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
    // What the consumers read the per-frame atlas from: map(), or with --shadow-raster compute
    // the rasterizer's depth buffer (float bits, row-major; no D32 atlas then).
    ResourceHandle sampledAtlas() const;
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
    // What a pass that calls recordLight declares (PerLight): the map as its DepthAttachment
    // and, when culled, the culled draws; nothing when not enabled().
    std::vector<PassUse> perLightUses() const;
    // Binds the set (nothing when not enabled()).
    void bind(VkCommandBuffer cmd, VkPipelineLayout layout, VkPipelineBindPoint point) const;
    // For Renderer::updateView: true when the plan changed its layout (other lights, other
    // sizes) since plan(): plan again. Cached: re-renders the kept atlas when a shadowed light
    // moved (or turned), between frames.
    bool stale();
    // After the frames (a renderer's collectStats): the faces' cull statistics of the frame
    // (nothing unless culled in the frame; the kept atlas reads its own after each render).
    void collect(FrameGraph& graph);

    // PerLight, inside a pass that declared map() as its DepthAttachment and has no rendering
    // open: renders light `light`'s faces and leaves the map readable by fragment and compute
    // shaders. endLight() returns it to the attachment layout (before the next light or the
    // end of the pass). A light the plan does not shadow records nothing.
    void recordLight(PassContext& pc, uint32_t light);
    void endLight(PassContext& pc);
    bool shadowed(uint32_t light) const;

    // Tests: the compute rasterizer's list of large triangles holds `n` (0: its default), so
    // that its overflow can be seen. Before plan().
    void setRasterListCapacity(uint32_t n) { listCapacity_ = n; }

    // Counters for a renderer's stats: shadowed lights, faces, map bytes, the draws of one
    // render of every face (shadow_face_draws), whether cached and its one-time render.
    std::vector<std::pair<std::string, double>> counters() const;

  private:
    void recordAtlas(PassContext& pc);
    void renderCached();
    void renderCachedCompute(VkCommandBuffer cmd);
    std::vector<gpu::LightGpu> shadowedLights() const; // world space, as rendered
    void recordFaces(VkCommandBuffer cmd, uint32_t firstFace, uint32_t faceCount, bool local);
    // faceDraws_ from the plan and the lights as they are now; false when culled in the frame
    // and the rows outgrew the planned buffers.
    bool cullFaces();
    void recordFaceDraws(VkCommandBuffer cmd, uint32_t face, VkPipeline& bound);

    GpuContext& ctx_;
    SceneGpu& scene_;
    Residency residency_;
    CullGeometry cullMode_;
    ShadowRaster rasterMode_;
    uint32_t listCapacity_ = 0;
    std::unique_ptr<ShadowCull> cull_; // with --cull-geometry frustum|full and shadows
    std::unique_ptr<ShadowComputeRaster> raster_; // with --shadow-raster compute
    ResourceHandle map_;
    FrameGraph* graph_ = nullptr;
    Image kept_;                              // the cached atlas
    // The per-frame atlas rasterized in compute: the consumers read its depth buffer, no copy.
    bool readsBuffer() const;
    std::vector<gpu::LightGpu> culledLights_; // the shadowed lights faceDraws_ (and kept_) are for
    // Per face, the draws that may reach it: culled once per plan and again when a shadowed
    // light moves, not at every recording.
    std::vector<std::vector<const DrawItem*>> faceDraws_;
    double faceDrawCount_ = 0, faceTriangles_ = 0; // one render of every face
    double keptRenderMs_ = 0;                 // its last one-time render, GPU time
    uint32_t keptRenders_ = 0;
    uint64_t generation_ = 0;
    PassSet set_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline opaque_ = VK_NULL_HANDLE, mask_ = VK_NULL_HANDLE;
};

} // namespace tp
