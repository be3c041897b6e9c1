#pragma once
#include <map>
// The passes of multipass forward, one file each: base_pass.cpp, light_passes.cpp,
// blended_pass.cpp, after the pass library's depth prepass (core/passes/depth_prepass.h). Each
// creates its pipelines in its constructor (after the graph allocated resources) and records into
// the targets below. They share the scene's pipeline layout (set 0 + DrawPush); set 1 is the
// blended light draws' light table with GPU blended lists (blended_light_draw_pass.h), else
// empty; with --shadows, set 2 is the one light's shadow map (shadowed_shading.cpp).
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/resources.h"
#include "multipass_forward/light_plan.h"
#include "multipass_forward/mp_settings.h"
#include "multipass_forward/multipass_shared.h"

namespace tp {
class GpuContext;
class ShadowMaps;
namespace passes {
class MeshletCull;
}
} // namespace tp

namespace tp::mp {

class LightDrawPass;
class BlendedLightDrawPass;

// The accumulation target and depth every pass renders into: the single-sample exported
// images at 1x, the per-sample ones under MSAA (resolved by the last pass into hdr).
// Depth with a stencil: the light passes mark each sample they lit, so that coincident surfaces
// (duplicated geometry, overlapping coplanar triangles), which all pass the EQUAL test, add a
// light once as the reference's GREATER test shades one of them (light_passes.cpp).
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;

struct Targets {
    ResourceHandle hdr, depth;         // exported
    ResourceHandle hdrMsaa, depthMsaa; // valid only when msaa > 1
    ResourceHandle color() const { return hdrMsaa.valid() ? hdrMsaa : hdr; }
    ResourceHandle depthTarget() const { return depthMsaa.valid() ? depthMsaa : depth; }
};

struct PassEnv {
    GpuContext& ctx;
    const SceneGpu& scene;
    const Settings& settings;
    const LightPlan& plan;
    VkPipelineLayout layout;
    VkFormat accumFormat; // RGBA16F or RGBA32F (the accum knob)
    // RenderSettings::manyViews: pipelines for every draw the scene has, not only for those on
    // screen in the planned view, so a new view's plan fits (the renderer's updateView).
    bool allDraws = false;
    // --shadows: one light's map (ShadowMaps::Residency::PerLight), rendered inside the light
    // and blended passes before each shadowed light (ShadowedShading); null or not enabled():
    // the passes record exactly what they recorded before shadows existed.
    ShadowMaps* shadows = nullptr;
    // --cull-geometry frustum: the prepass, base and light passes draw the meshlets this pass
    // kept of their opaque and masked draws (drawOpaque); null: the meshes whole. The blended
    // pass always draws whole meshes (its triangle order is its own).
    const passes::MeshletCull* cull = nullptr;
    // --light-draws gpu: the light passes draw each light's indirect draws written by this pass
    // (whole meshes, also under --cull-geometry); null: the plan's CPU lists.
    const LightDrawPass* lightDraws = nullptr;
    // --light-draws gpu with --blended-lights under (no shadows, dualSrcBlend): each blended
    // draw's light draws and resets are this pass's indirect draws (one dual-source pipeline, the
    // light's slot in firstInstance, set TP_SET_PASS its light table); null: the plan's lists.
    const BlendedLightDrawPass* blendedLightDraws = nullptr;
};

// Frame-graph uses of a pass that blends into the accumulation target with the prepass
// depth read-only (`stencil`: depth tested, never written, and the stencil written);
// `resolve`: this is the last such pass and averages into hdr.
std::vector<PassUse> shadingUses(const Targets& t, bool resolve, bool stencil = false);
// beginRendering for those uses (`clear`: the base pass starts the accumulation; `stencil`:
// the stencil attachment too, cleared to 0).
void beginShading(PassContext& pc, const Targets& t, bool resolve, bool clear,
                  bool stencil = false);
// The fragment shader `mp_STEM_frag`, or its once-per-pixel variant `mp_STEM_pixel_frag`
// (inputs at the pixel centre) under MSAA with --msaa-shading pixel.
std::string fragmentShader(const PassEnv& env, const std::string& stem);
// The frame-graph use of the shadow map by a pass that renders it (none without shadows).
void addShadowUse(std::vector<PassUse>& uses, const ShadowMaps* shadows);
// The shadowed twin of a light pipeline (mp_light_shadow_frag: evalLightShadowed with the
// map); VK_NULL_HANDLE without shadows.
VkPipeline createShadowedTwin(const PassEnv& env, GraphicsPipelineDesc d);

// A shading pass's rendering, split where a shadowed light needs its map (--shadows): the map
// can only be rendered with no rendering open, so before the first draw of a shadowed light
// whose map is not already held, the accumulation's rendering ends, ShadowMaps::recordLight
// renders the light's faces, a barrier orders the next rendering's load after the last one's
// blending, and the rendering begins again (load). The map stays held across unshadowed
// lights (they use the plain pipeline, which never reads it) and across consecutive draws of
// the same light (blended draws); the MSAA resolve goes only into the last rendering. Without
// shadows: one beginShading ... endRendering, as before.
class ShadowedShading {
  public:
    // `order`: every light the pass will hold(), in order (to know which rendering is last).
    // `stencil`: the renderings have the stencil attachment (beginShading).
    ShadowedShading(PassContext& pc, const Targets& t, bool resolve, ShadowMaps* shadows,
                    const std::vector<uint32_t>& order, bool stencil = false);
    bool shadowed(uint32_t light) const;
    // Before shading `light`: true when the rendering began again (bind everything again).
    bool hold(uint32_t light);
    void end(); // ends the rendering and returns the map to its attachment layout
    uint32_t mapRenders() const { return renders_; }

  private:
    PassContext& pc_;
    const Targets& t_;
    const bool resolve_, stencil_;
    ShadowMaps* shadows_;
    uint32_t switchesLeft_ = 0, renders_ = 0;
    uint32_t held_ = ~0u; // the light the map holds (readable), ~0u: none
};

// Pipeline description shared by the shading passes: per-sample shading under MSAA with
// --msaa-shading sample (the reference's rate), else once per pixel; scene layout,
// accumulation format.
GraphicsPipelineDesc shadingDesc(const PassEnv& env, AlphaMode mode);
// Draws are recorded with recordDraw (core/gpuscene/scene_gpu.h); a light pass
// gives its light as DrawPush.pad0 (TP_MP_LIGHT_INDEX), ignored by non-light shaders.
// Binds `pipeline`, the scene set and the index buffer drawOpaque's draws read (the meshlet
// index buffer when culled): what the base and light passes' draw loops need.
void bindSceneDraws(VkCommandBuffer cmd, const PassEnv& env, VkPipeline pipeline);
// One opaque or masked draw: its culled meshlets (env.cull) or the whole mesh.
void drawOpaque(PassContext& pc, const PassEnv& env, const DrawItem& d, uint32_t pad0 = 0);
void setScissor(VkCommandBuffer cmd, const ScreenRect& r);
void destroyPipeline(GpuContext& ctx, VkPipeline& pipeline);

// 2. Ambient + emissive + directional lights of opaque and masked surfaces, depth EQUAL.
class BasePass {
  public:
    explicit BasePass(const PassEnv& env);
    ~BasePass();
    // clear: the accumulation is cleared by this pass (false: base_hdr_clear zeroed it).
    void record(PassContext& pc, const Targets& t, bool resolve, bool clear);
    uint32_t draws() const { return draws_; }
    bool hasPipeline() const { return pipeline_ != VK_NULL_HANDLE; }

  private:
    const PassEnv env_;
    VkDescriptorSet litSet_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    uint32_t draws_ = 0;
};

// 3. Every local light's additive pass over the opaque and masked draws it touches,
// scissored to the light's screen rectangle; one graph pass, so one timing.
class LightPasses {
  public:
    // litSet: count the fragments that evaluate their light into its TP_MP_BINDING_LIT (a GPU
    // with pass statistics; env.layout then holds the scene set, it and the shadow set); null:
    // the plain variants, which count nothing.
    LightPasses(const PassEnv& env, const PassSet* litSet);
    ~LightPasses();
    void record(PassContext& pc, const Targets& t, bool resolve);
    // Draws recorded: with CPU lists one per light and mesh; with GPU lists (env.lightDraws)
    // the indirect calls (the draws they issue are the GPU's light_draw_meshes).
    uint32_t draws() const { return draws_; }
    uint32_t mapRenders() const { return mapRenders_; } // shadow maps rendered (--shadows)
    bool hasPipeline() const { return pipeline_ != VK_NULL_HANDLE; }

  private:
    void bind(PassContext& pc, VkPipeline pipeline) const;
    void recordDraws(PassContext& pc, const LightBatch& batch);

    const PassEnv env_;
    VkDescriptorSet litSet_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipeline shadowed_ = VK_NULL_HANDLE; // --shadows: the twin, for the shadowed lights
    uint32_t draws_ = 0, mapRenders_ = 0;
};

// 4. Blended draws back to front; each one's base pass composites over what is behind it,
// then each light adds under the draw's own layers (reverse triangle order, transmittance
// in the target's alpha), before the next draw starts.
class BlendedPass {
  public:
    explicit BlendedPass(const PassEnv& env);
    ~BlendedPass();
    void record(PassContext& pc, const Targets& t, bool resolve);
    // With GPU lists (env.blendedLightDraws) the composites alone: the light draws and resets
    // are the GPU's (blended_light_draw_meshes), counted after the frame by the renderer.
    uint32_t draws() const { return draws_; }
    uint32_t lightDraws() const { return lightDraws_; } // of draws(); under: each has a reset too
    uint32_t mapRenders() const { return mapRenders_; } // shadow maps rendered (--shadows)
    bool hasPipelines() const { return base_ != VK_NULL_HANDLE; }
    // After the plan changed (a new view): the reversed triangles of every draw lit now.
    void follow();
    // A blended draw's first index in blended_indices_reversed (it has lights, or GPU lists).
    uint32_t reversedFirst(const DrawItem* draw) const { return reversedFirst_.at(draw); }

  private:
    void createReversedIndices();
    void recordUnderLights(PassContext& pc, const BlendedDraw& bd, ShadowedShading& shading);
    void recordAdditiveLights(PassContext& pc, const BlendedDraw& bd, ShadowedShading& shading);
    void recordGpuLights(PassContext& pc, uint32_t b);
    void createGpuLightPipeline(GraphicsPipelineDesc d);
    // Before a light's draws: the map (ShadowedShading::hold) and this light's pipeline.
    void bindLight(PassContext& pc, ShadowedShading& shading, uint32_t light, VkBuffer indices);

    const PassEnv env_;
    const bool additive_; // --blended-lights additive: the textbook pass, no reversed order
    const bool onePass_;  // --blended-lights one-pass: every light in the composite, no light draws
    VkPipeline base_ = VK_NULL_HANDLE, light_ = VK_NULL_HANDLE, reset_ = VK_NULL_HANDLE;
    VkPipeline lightShadowed_ = VK_NULL_HANDLE; // --shadows: light_'s twin
    VkPipeline lightGpu_ = VK_NULL_HANDLE; // GPU lists: light draws and resets (dual source)
    VkPipeline bound_ = VK_NULL_HANDLE;         // while recording
    Buffer reversedIndices_;              // lit blended draws, triangles in reverse order
    std::map<const DrawItem*, uint32_t> reversedFirst_; // a lit draw's first index there
    uint32_t draws_ = 0, lightDraws_ = 0, mapRenders_ = 0;
};

} // namespace tp::mp
