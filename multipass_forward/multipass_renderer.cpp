#include "multipass_forward/multipass_renderer.h"

#include <optional>

#include "core/calibrate/material_fetches.h"
#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/depth_prepass.h"
#include "core/passes/image_clear.h"
#include "core/passes/meshlet_cull.h"
#include "core/passes/shadow_maps.h"
#include "multipass_forward/blended_light_draw_pass.h"
#include "multipass_forward/light_count.h"
#include "multipass_forward/light_draw_pass.h"
#include "multipass_forward/passes.h"

namespace tp {
namespace {

using namespace mp;

uint32_t localLightCount(const SceneGpu& scene) {
    uint32_t directional = 0, local = 0;
    for (const gpu::LightGpu& l : scene.shadingLights())
        ++(l.type == TP_LIGHT_DIRECTIONAL ? directional : local);
    return local + (directional > TP_MP_MAX_BASE_DIRECTIONAL
                        ? directional - TP_MP_MAX_BASE_DIRECTIONAL
                        : 0);
}

// --light-draws gpu where the device and the size allow it (why not: `why`), else cpu.
LightLists chooseLists(const RendererCreateInfo& info, const Settings& s, std::string& why) {
    if (s.lightLists == LightLists::Cpu) return LightLists::Cpu;
    why = LightDrawPass::unavailable(info.ctx, info.scene, localLightCount(info.scene));
    return why.empty() ? LightLists::Gpu : LightLists::Cpu;
}

// The blended draws' lights on the GPU too (--light-draws gpu-blended) where the opaque lists
// are, the blended draws are lit by light draws composited under (not additive, not one-pass),
// no light is shadowed (a map is rendered between two lights' draws) and the device blends
// dual-source; `why` says why not where it matters (a scene with blended draws lit by light
// draws). Not under plain gpu: without a scissor each light draw rasterizes its whole mesh, which
// cost the H200's frame 18 % at 1,024 lights (docs/multipass_forward.md).
LightLists chooseBlendedLists(const RendererCreateInfo& info, const Settings& s, LightLists lists,
                              std::string& why) {
    if (s.lightLists != LightLists::GpuBlended || lists == LightLists::Cpu ||
        s.blendedLights == BlendedLights::OnePass ||
        !info.scene.hasDraws(DrawFilter::Blend))
        return LightLists::Cpu;
    why = BlendedLightDrawPass::unavailable(info.ctx, info.scene, localLightCount(info.scene),
                                            !info.scene.shadowPlan().empty(),
                                            s.blendedLights == BlendedLights::Additive);
    return why.empty() ? LightLists::Gpu : LightLists::Cpu;
}

class MultipassForwardRenderer final : public Renderer {
  public:
    explicit MultipassForwardRenderer(const RendererCreateInfo& info)
        : ctx_(info.ctx), scene_(info.scene), mp_(readSettings(info.settings)),
          accumFormat_(mp_.accum == Accum::Fp16 ? VK_FORMAT_R16G16B16A16_SFLOAT
                                                : VK_FORMAT_R32G32B32A32_SFLOAT),
          manyViews_(info.settings.manyViews), lists_(chooseLists(info, mp_, listsWhy_)),
          blendedLists_(chooseBlendedLists(info, mp_, lists_, blendedWhy_)), plan_(newPlan()),
          lightCount_(info.ctx, info.scene, info.settings.passStatistics) {}

    ~MultipassForwardRenderer() override {
        cull_.reset();
        lightDraws_.reset();
        blendedDraws_.reset();
        prepass_.reset();
        base_.reset();
        lights_.reset();
        blended_.reset();
        shadows_.reset();
        if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    }

    void plan(FrameGraph& graph) override {
        createTargets(graph);
        // --shadows: one light's map ("shadow_map"), rendered by the light and blended passes.
        shadows_.emplace(ctx_, scene_, ShadowMaps::Residency::PerLight, mp_.cullGeometry,
                         mp_.shadowRaster);
        shadows_->plan(graph);
        // The last pass that shades resolves the per-sample target into hdr.
        // Many views: the passes every view may need, whether or not this one does.
        hasLights_ = !plan_.batches.empty() || (manyViews_ && plan_.localLights > 0);
        hasBlended_ = !plan_.blended.empty() || (manyViews_ && scene_.hasDraws(DrawFilter::Blend));
        const bool hasLights = hasLights_, hasBlended = hasBlended_;
        passes::DepthPrepassParams prepass{mp_.sampling.samples, plan_.opaque, plan_.masked,
                                           manyViews_, kDepthFormat};
        // Every opaque and masked draw of the scene, not only those on screen now: the
        // passes record the on-screen ones of each view (updateView) from the same slots.
        prepass.cull = passes::planOpaqueCull(cull_, ctx_, scene_, graph, mp_.cullGeometry);
        prepass_ = std::make_unique<passes::DepthPrepass>(ctx_, scene_, std::move(prepass));
        prepass_->plan(graph,
                       {t_.depthTarget(), t_.depthMsaa.valid() ? t_.depth : ResourceHandle{}});
        bool last = !hasLights && !hasBlended;
        // The accumulation zeroed by compute where the device can store to it, not by the base
        // pass's render pass (on the H200 that clear runs on the graphics SMs: docs/efficiency.md,
        // "Clears").
        hdrClear_.emplace(ctx_);
        hdrClear_->plan(graph, "base_hdr_clear", t_.color(), ColorTarget{}.clearValue);
        graph.addPass("base_pass", withCullUses(shadingUses(t_, last)),
                      [this, last](PassContext& pc) {
                          base_->record(pc, t_, last, !hdrClear_->planned());
                      });
        if (hasLights) {
            last = !hasBlended;
            std::vector<PassUse> uses = withCullUses(shadingUses(t_, last, true));
            if (lists_ == LightLists::Gpu && !passes::opaqueAndMaskedDraws(scene_).empty()) {
                // Each light's draws, written on the GPU every frame (light_draw_pass.h).
                lightDraws_.emplace(ctx_, scene_, plan_.localLights,
                                    !mp_.sampling.perPixelUnderMsaa());
                lightDraws_->plan(graph);
                for (const PassUse& u : lightDraws_->drawUses())
                    uses.push_back(u);
            }
            addShadowUse(uses, &*shadows_);
            lightCount_.plan(graph, uses);
            graph.addPass("light_passes", uses,
                          [this, last](PassContext& pc) { lights_->record(pc, t_, last); });
        }
        if (hasBlended) {
            std::vector<PassUse> uses = shadingUses(t_, true);
            if (blendedLists_ == LightLists::Gpu) {
                // Each blended draw's light draws and resets, written on the GPU every frame.
                blendedDraws_.emplace(ctx_, scene_, plan_.localLights);
                blendedDraws_->plan(graph);
                for (const PassUse& u : blendedDraws_->drawUses())
                    uses.push_back(u);
            }
            if (lightBlended()) addShadowUse(uses, &*shadows_); // one-pass: no light passes
            graph.addPass("blended", uses,
                          [this](PassContext& pc) { blended_->record(pc, t_, true); });
        }
        graph.exportResource("hdr", t_.hdr);
        graph.exportResource("depth", t_.depth);
    }

    void prepare(FrameGraph& graph) override {
        hdrClear_->prepare(graph);
        shadows_->prepare(graph);
        if (blendedDraws_) blendedDraws_->prepare(graph);
        // Set TP_SET_PASS: the blended light draws' light table (GPU lists; no shadows then).
        layout_ = scene_.createPipelineLayout(
            blendedDraws_ ? blendedDraws_->lightSetLayout() : VK_NULL_HANDLE,
            shadows_->setLayout());
        PassEnv env{ctx_,       scene_,     mp_,
                    plan_,      layout_,    accumFormat_,
                    manyViews_, &*shadows_, cull_ ? &*cull_ : nullptr,
                    lightDraws_ ? &*lightDraws_ : nullptr,
                    blendedDraws_ ? &*blendedDraws_ : nullptr};
        if (cull_) cull_->prepare(graph);
        if (lightDraws_) {
            lightDraws_->prepare(graph);
            lightDraws_->update(plan_);
        }
        prepass_->prepare();
        base_ = std::make_unique<BasePass>(env);
        lights_ = std::make_unique<LightPasses>(
            lightCount_.prepare(graph, env, shadows_->setLayout()), lightCount_.set());
        blended_ = std::make_unique<BlendedPass>(env);
        updateBlendedDraws();
    }

    // The light plan again for the new view, kept where the planned passes and pipelines can
    // record it: with GPU lists the scissors, the draws on screen and the blended draws' lights
    // (the per-light lists of opaque and masked draws are the light-draws pass's, every frame);
    // with CPU lists those lists too.
    bool updateView(FrameGraph&) override {
        if (shadows_->stale()) return false; // other shadowed lights or map sizes
        LightPlan next = newPlan();
        const bool fits = next.baseDirectional == plan_.baseDirectional && // spec constants
                          (next.batches.empty() || hasLights_) &&
                          (next.blended.empty() || (hasBlended_ && blended_->hasPipelines())) &&
                          ((next.opaque.empty() && next.masked.empty()) || base_->hasPipeline()) &&
                          (next.batches.empty() || (lights_ && lights_->hasPipeline()));
        if (!fits || !prepass_->setDraws(next.opaque, next.masked)) return false;
        plan_ = std::move(next);
        if (lightDraws_) lightDraws_->update(plan_);
        blended_->follow();
        updateBlendedDraws();
        return true;
    }

    // With GPU lists each light's meshes come from the frame: the counters over every light
    // (lights_skipped, meshes_per_light_*) are complete only after it.
    void collectStats(FrameGraph& graph) override {
        if (cull_) cull_->collect(graph);
        if (lightDraws_) lightDraws_->collect(graph);
        if (blendedDraws_) blendedDraws_->collect(graph);
        if (lightDraws_ || blendedDraws_)
            mergeGpuMeshes(plan_, lightDraws_ ? lightDraws_->meshes() : std::vector<uint32_t>{},
                           blendedDraws_ ? blendedDraws_->meshes() : std::vector<uint32_t>{});
        if (shadows_) shadows_->collect(graph);
        lightCount_.collect(graph);
    }

    RendererStats stats() const override;

  private:
    // A pass that draws opaque and masked meshes (drawOpaque) reads the culled commands.
    std::vector<PassUse> withCullUses(std::vector<PassUse> uses) const {
        if (cull_)
            for (const PassUse& u : cull_->drawUses())
                uses.push_back(u);
        return uses;
    }

    void shadowStats(RendererStats& s) const;
    void addPassWork(RendererStats& s) const;
    bool lightBlended() const { return mp_.blendedLights != BlendedLights::OnePass; }
    LightPlan newPlan() {
        if (lists_ == LightLists::Cpu) ++cpuListBuilds_;
        if (blendedLists_ == LightLists::Cpu && lightBlended()) ++cpuBlendedBuilds_;
        return planLights(scene_, lightBlended(), lists_, blendedLists_);
    }
    // The blended draws on screen, with their reversed index ranges, for the GPU's lists.
    void updateBlendedDraws() {
        if (blendedDraws_)
            blendedDraws_->update(plan_,
                                  [this](const DrawItem* d) { return blended_->reversedFirst(d); });
    }
    // The blended light draws (of blended_draws; under: each has a reset too): with GPU lists
    // those the frame issued (0 before a frame).
    uint32_t blendedLightDraws() const;
    // The light passes' draws: with GPU lists those the frame issued (0 before a frame).
    uint32_t lightPassDraws() const;

    void createTargets(FrameGraph& graph) {
        const bool fp16 = accumFormat_ == VK_FORMAT_R16G16B16A16_SFLOAT;
        const std::string accum = fp16 ? "accumulated radiance, fp16 (resolved)"
                                       : "accumulated radiance, fp32 (resolved)";
        t_.hdr = graph.createImage("hdr", {accumFormat_, 0, 0, VK_SAMPLE_COUNT_1_BIT, accum});
        t_.depth = graph.createImage("depth", {kDepthFormat, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                               "prepass depth (resolved: sample 0)"});
        if (mp_.sampling.samples > 1) {
            const auto samples = VkSampleCountFlagBits(mp_.sampling.samples);
            t_.hdrMsaa = graph.createImage(
                "hdr_msaa", {accumFormat_, 0, 0, samples, "per-sample accumulation"});
            t_.depthMsaa = graph.createImage(
                "depth_msaa", {kDepthFormat, 0, 0, samples, "per-sample prepass depth"});
        }
    }

    GpuContext& ctx_;
    SceneGpu& scene_;
    Settings mp_;
    VkFormat accumFormat_;
    bool manyViews_;
    bool hasLights_ = false, hasBlended_ = false; // the passes planned
    std::string listsWhy_; // why --light-draws gpu fell back to the CPU (empty: it did not)
    LightLists lists_;
    std::string blendedWhy_;    // why the blended draws' lights stay on the CPU with gpu lists
    LightLists blendedLists_;   // who selects each blended draw's lights
    uint32_t cpuListBuilds_ = 0; // per-light lists of opaque and masked draws built on the CPU
    uint32_t cpuBlendedBuilds_ = 0; // views whose blended draws' lights the CPU planned
    LightPlan plan_;
    Targets t_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    LightCount lightCount_; // the light passes' fragments that evaluate their light
    std::optional<ShadowMaps> shadows_; // one light's map (shadow_map) with --shadows
    std::optional<passes::MeshletCull> cull_; // --cull-geometry frustum: meshlet_cull
    std::optional<LightDrawPass> lightDraws_; // --light-draws gpu: light_draws
    std::optional<BlendedLightDrawPass> blendedDraws_; // and blended_light_draws
    std::unique_ptr<passes::DepthPrepass> prepass_;
    std::optional<ImageClear> hdrClear_; // base_hdr_clear, where the device can store to it
    std::unique_ptr<BasePass> base_;
    std::unique_ptr<LightPasses> lights_;
    std::unique_ptr<BlendedPass> blended_;
};

uint32_t MultipassForwardRenderer::lightPassDraws() const {
    if (!lightDraws_) return lights_ ? lights_->draws() : 0;
    uint32_t draws = 0;
    for (const LightBatch& b : plan_.batches) // the lights recorded (off-screen ones are not)
        draws += lightDraws_->meshes().empty() ? 0 : lightDraws_->meshes()[b.slot];
    return draws;
}

uint32_t MultipassForwardRenderer::blendedLightDraws() const {
    if (!blendedDraws_) return blended_ ? blended_->lightDraws() : 0;
    uint32_t draws = 0;
    for (uint32_t m : blendedDraws_->meshes()) draws += m;
    return draws;
}

RendererStats MultipassForwardRenderer::stats() const {
    RendererStats s;
    auto count = [&](const std::string& name, double v) { s.counters.push_back({name, v}); };
    shadowStats(s);
    // With GPU blended lists the pass records the composites; each light draw has its reset.
    const uint32_t lightDraws = lightPassDraws(), blendLightDraws = blendedLightDraws(),
                   blendDraws = (blended_ ? blended_->draws() : 0) +
                                (blendedDraws_ ? 2 * blendLightDraws : 0);
    const uint32_t prepassDraws = prepass_ ? prepass_->draws() : 0,
                   lateDraws = prepass_ ? prepass_->lateDraws() : 0,
                   baseDraws = base_ ? base_->draws() : 0;
    count("draws", double(prepassDraws + lateDraws + baseDraws + lightDraws + blendDraws));
    count("depth_prepass_draws", prepassDraws);
    count("depth_prepass_late_draws", lateDraws); // --cull-geometry full: the occlusion's second
    count("base_pass_draws", baseDraws);
    count("light_passes_draws", lightDraws);
    count("blended_draws", blendDraws);
    count("blended_light_draws", blendLightDraws);
    // The draws placed against draw_culled (docs/efficiency.md): a draw per light and mesh is
    // this architecture's cost that no pixel or triangle count shows.
    for (const auto& [pass, draws] : {std::pair{"depth_prepass", prepassDraws},
                                      {"depth_prepass_late", lateDraws},
                                      {"base_pass", baseDraws},
                                      {"light_passes", lightDraws},
                                      {"blended", blendDraws}})
        if (draws > 0)
            s.opWork.push_back({pass, PassOpWork::Kind::Draws, PassLightWork::Base::Items, 1.0,
                                true, "the draws recorded, or selected on the GPU (counter " +
                                          std::string(pass) + "_draws)",
                                double(draws)});
    count("local_lights", plan_.localLights);
    count("lights_skipped", plan_.lightsSkipped);
    count("base_pass_directional_lights", double(plan_.baseDirectional.size()));
    count("meshes_per_light_mean",
          plan_.localLights ? double(plan_.meshesPerLightSum) / double(plan_.localLights) : 0.0);
    count("meshes_per_light_max", plan_.meshesPerLightMax);
    count("accumulation_bits", accumFormat_ == VK_FORMAT_R16G16B16A16_SFLOAT ? 16.0 : 32.0);
    // --light-draws: 1 where the GPU selects each light's draws; the indirect calls recorded
    // for them; how often the CPU built per-light lists (with gpu: never, on any view).
    count("light_draws_gpu", lightDraws_ ? 1.0 : 0.0);
    if (lightDraws_) count("light_passes_indirect_calls", lights_ ? lights_->draws() : 0);
    if (lightDraws_ && lightDraws_->collected()) { // the spans of meshlets the lights reach
        double triangles = 0;
        for (const LightBatch& b : plan_.batches)
            triangles += lightDraws_->triangles()[b.slot];
        count("light_passes_triangles", triangles);
    }
    count("light_lists_cpu_builds", cpuListBuilds_);
    // The same for the blended draws' lights (blended draws x lights tests on the CPU per view).
    count("blended_light_draws_gpu", blendedDraws_ ? 1.0 : 0.0);
    count("blended_light_lists_cpu_builds", cpuBlendedBuilds_);
    if (cull_) { // --cull-geometry frustum: meshlets and triangles, submitted and culled
        for (const auto& c : cull_->counters())
            s.counters.push_back(c);
        // The indirect draws the light passes issue: each light's meshes' kept meshlets (a
        // CPU device runs each as a draw of its own; docs/geometry.md).
        double meshletDraws = 0;
        for (const LightBatch& b : plan_.batches)
            for (const DrawItem* d : b.draws)
                meshletDraws += cull_->kept(*d);
        if (cull_->collected() && !lightDraws_) count("light_passes_meshlet_draws", meshletDraws);
        if (lightDraws_)
            s.leftOut.push_back({"meshlet culling in light_passes",
                                 "--light-draws gpu draws, of each lit mesh, the span of "
                                 "meshlets its light reaches, not culled by the view (the "
                                 "prepass and base pass keep their culled meshlets)"});
    }
    if (!listsWhy_.empty())
        s.leftOut.push_back({"light_draws (--light-draws gpu)", listsWhy_ + ": lists on the CPU"});
    if (!blendedWhy_.empty())
        s.leftOut.push_back({"blended_light_draws (--light-draws gpu)",
                             blendedWhy_ + ": the blended draws' lights on the CPU"});
    if (plan_.batches.empty())
        s.leftOut.push_back({"light_passes", plan_.localLights
                                                 ? "no local light touches a mesh on screen"
                                                 : "no point or spot lights"});
    if (plan_.blended.empty())
        s.leftOut.push_back({"blended pass", scene_.hasDraws(DrawFilter::Blend)
                                                 ? "no blended draw on screen"
                                                 : "no blended materials"});
    if (mp_.sampling.samples == 1) s.leftOut.push_back({"per-sample targets", "MSAA is 1x"});
    if (!plan_.blended.empty() && mp_.blendedLights == BlendedLights::Additive)
        s.leftOut.push_back({"blended_indices_reversed and transmittance resets",
                             "--blended-lights additive (the textbook pass: not exact where a "
                             "blended mesh overlaps itself)"});
    if (!plan_.blended.empty() && mp_.blendedLights == BlendedLights::OnePass)
        s.leftOut.push_back({"blended light passes",
                             "--blended-lights one-pass: every light in the blended composite"});
    if (plan_.masked.empty())
        s.leftOut.push_back({"masked prepass pipeline", "no masked draw on screen"});
    addPassWork(s);
    return s;
}

// Counted work per pass (docs/efficiency.md). A light pass's fragment evaluates its one light,
// the base pass's the directional lights; the blended pass's: mp_settings.h says.
void MultipassForwardRenderer::addPassWork(RendererStats& s) const {
    using Base = PassLightWork::Base;
    const double dir = double(plan_.baseDirectional.size());
    const BlendedLights mode = mp_.blendedLights;
    lightCount_.addWork(s, hasLights_); // the light passes: what the shader counted
    s.lightWork.push_back(
        {"base_pass", Base::Fragments, dir, true, "the directional lights, per fragment"});
    s.lightWork.push_back(
        {"blended", Base::Fragments, blendedLightsPerFragment(mode, dir, scene_.lightCount()),
         mode == BlendedLights::OnePass,
         "at least: composites the directional lights, light draws one, resets none"});
    s.opWork.push_back(materialFetchWork(scene_, "base_pass", {DrawFilter::Opaque, DrawFilter::Mask},
                                         Base::Fragments));
    s.opWork.push_back(materialFetchWork(scene_, "blended", {DrawFilter::Blend}, Base::Fragments,
                                         blendedSamplingShare(mode)));
}

// ShadowMaps' counters, with the renders this pipeline made: one per shadowed light that lights
// an opaque mesh on screen, plus one per change of light among the blended draws' light
// passes (the map holds one light; a light that lights several blended draws is rendered
// again for each run of them).
void MultipassForwardRenderer::shadowStats(RendererStats& s) const {
    if (!shadows_ || !shadows_->enabled()) return;
    const double lightRenders = lights_ ? lights_->mapRenders() : 0,
                 blendedRenders = blended_ ? blended_->mapRenders() : 0;
    for (auto [name, value] : shadows_->counters())
        s.counters.push_back(
            {name, name == "shadow_map_renders_per_frame" ? lightRenders + blendedRenders : value});
    s.counters.push_back({"light_passes_shadow_renders", lightRenders});
    s.counters.push_back({"blended_shadow_renders", blendedRenders});
    if (!lightBlended() && !plan_.blended.empty())
        s.leftOut.push_back({"blended shadows", "--blended-lights one-pass shades every light at "
                                                "once; one light's map is resident: blended "
                                                "surfaces are lit unshadowed"});
}

} // namespace

std::unique_ptr<Renderer> createMultipassForwardRenderer(const RendererCreateInfo& info) {
    return std::make_unique<MultipassForwardRenderer>(info);
}

} // namespace tp
