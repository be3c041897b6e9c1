#include "core/reference/reference_renderer.h"

#include <optional>

#include "core/calibrate/material_fetches.h"
#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/shadow_maps.h"
#include "core/reference/reference_settings.h"
#include "core/reference/shadow_rays.h"

namespace tp {
namespace {

class ReferenceRenderer final : public Renderer {
  public:
    explicit ReferenceRenderer(const RendererCreateInfo& info)
        : ctx_(info.ctx), scene_(info.scene), features_(info.features), settings_(info.settings),
          ref_(ref::readSettings(info.settings)), shadowed_(ref::anyLightShadowed(info.scene)) {
        fp64_ = ref_.precision == ref::Precision::Fp64 && ctx_.caps.float64;
    }

    ~ReferenceRenderer() override {
        for (VkPipeline p : pipelines_)
            if (p) vkDestroyPipeline(ctx_.device, p, nullptr);
        if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
        if (passSet_.layout) destroyPassSet(ctx_, passSet_);
    }

    void plan(FrameGraph& graph) override {
        const auto samples = VkSampleCountFlagBits(settings_.msaa);
        hdr_ = graph.createImage("hdr", {VK_FORMAT_R32G32B32A32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                         "linear radiance (resolved)"});
        depth_ = graph.createImage("depth", {VK_FORMAT_D32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                             "depth (resolved: sample 0)"});
        std::vector<PassUse> uses;
        if (settings_.msaa > 1) {
            hdrMsaa_ = graph.createImage(
                "hdr_msaa", {VK_FORMAT_R32G32B32A32_SFLOAT, 0, 0, samples, "per-sample radiance"});
            depthMsaa_ = graph.createImage(
                "depth_msaa", {VK_FORMAT_D32_SFLOAT, 0, 0, samples, "per-sample depth"});
            uses = {{hdrMsaa_, Use::ColorAttachment},
                    {depthMsaa_, Use::DepthAttachment},
                    {hdr_, Use::ColorResolve},
                    {depth_, Use::DepthResolve}};
        } else {
            uses = {{hdr_, Use::ColorAttachment}, {depth_, Use::DepthAttachment}};
        }
        if (usesMaps()) { // the pipelines' atlas (shadow_maps), sampled as they sample it
            maps_.emplace(ctx_, scene_, ShadowMaps::Residency::Atlas, ref_.mapsCull,
                          ref_.mapsRaster);
            maps_->plan(graph);
            for (const PassUse& u : maps_->sampledUses()) uses.push_back(u);
        }
        graph.addPass(kPass, uses, [this](PassContext& pc) { record(pc); });
        graph.exportResource("hdr", hdr_);
        graph.exportResource("depth", depth_);
    }

    void prepare(FrameGraph& graph) override {
        // Shadowed lights: the TP_SHADOW_RAYS variants, with the BVH in set 1. Otherwise the
        // shaders and layout of a run without shadows, untouched.
        // --reference-shadows maps: the _shadow twins (TP_SHADOW_MAPS) with the maps in set 2.
        if (usesRays()) {
            rays_ = std::make_unique<ref::ShadowRayScene>(ctx_, scene_, kPass);
            passSet_ = graph.createPassSet(kPass, VK_NULL_HANDLE, rays_->externals());
        }
        if (maps_) maps_->prepare(graph);
        layout_ = scene_.createPipelineLayout(passSet_.layout, maps_ ? maps_->setLayout() : VK_NULL_HANDLE);
        GraphicsPipelineDesc d;
        const bool center = settings_.msaa > 1 && ref_.msaa == ref::MsaaMode::Center;
        const std::string base = std::string(center ? "reference_center" : "reference");
        const std::string precision =
            std::string(usesRays() ? "_rays" : "") + (fp64_ ? "_fp64_frag" : "_frag");
        d.colorFormats = {VK_FORMAT_R32G32B32A32_SFLOAT};
        d.samples = VkSampleCountFlagBits(settings_.msaa);
        d.sampleShading = settings_.msaa > 1;
        d.layout = layout_;
        d.passSet = usesRays() ? &passSet_ : nullptr;
        for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend}) {
            if (!scene_.hasDraws(DrawFilter(mode))) continue;
            d.specConstants = scene_.specConstants(mode);
            // --reference-position depth: what a G-buffer holds (opaque, masked) is lit at the
            // position reconstructed from depth; blended surfaces stay forward-lit, as in deferred.
            const bool fromDepth = positionFromDepth() && mode != AlphaMode::Blend;
            d.fragmentShader = base + (fromDepth ? "_depth" : "") + precision;
            if (maps_) maps_->apply(d.fragmentShader, d.specConstants);
            d.depthWrite = mode != AlphaMode::Blend;
            d.blend = mode == AlphaMode::Blend ? BlendMode::Alpha : BlendMode::None;
            pipelines_[uint32_t(mode)] = createGraphicsPipeline(ctx_, d);
        }
    }

    // Every light at every sample: nothing derives from the view but the blended draws' back-
    // to-front order, which the recording takes from the scene, and which shaders run: a view
    // whose lights start or stop casting shadows is planned again.
    bool updateView(FrameGraph&) override {
        if (maps_ && maps_->stale()) return false;
        return ref::anyLightShadowed(scene_) == shadowed_;
    }

    RendererStats stats() const override {
        RendererStats s;
        if (maps_) s.counters = maps_->counters();
        s.counters.push_back({"accumulation_bits", fp64_ ? 64.0 : 32.0});
        s.counters.push_back({"lights_evaluated_per_sample", double(scene_.lightCount())});
        if (settings_.msaa > 1)
            s.counters.push_back(
                {"shaded_at_pixel_center", ref_.msaa == ref::MsaaMode::Center ? 1.0 : 0.0});
        if (!fp64_)
            s.leftOut.push_back(
                {"fp64 accumulation", ref_.precision == ref::Precision::Fp64
                                          ? "device has no shaderFloat64"
                                          : "fp32 chosen (--reference-precision fp32)"});
        if (settings_.msaa == 1) s.leftOut.push_back({"per-sample targets", "MSAA is 1x"});
        if (rays_) rays_->addStats(s);
        s.lightWork.push_back({"reference_shading", PassLightWork::Base::Fragments, double(scene_.lightCount()),
                               true, "every light, per fragment (sample)"});
        s.opWork.push_back(materialFetchWork(
            scene_, "reference_shading", {DrawFilter::Opaque, DrawFilter::Mask, DrawFilter::Blend},
            PassLightWork::Base::Fragments));
        return s;
    }

  private:
    bool usesRays() const { return shadowed_ && ref_.shadows == ref::Shadows::Rays; }
    bool usesMaps() const { return shadowed_ && ref_.shadows == ref::Shadows::Maps; }
    bool positionFromDepth() const { return ref_.position == ref::Position::Depth; }

    void record(PassContext& pc) {
        std::optional<DepthTarget> depth;
        ColorTarget color;
        if (settings_.msaa > 1) {
            color = {hdrMsaa_, hdr_};
            depth = DepthTarget{depthMsaa_, depth_};
        } else {
            color = {hdr_, {}};
            depth = DepthTarget{depth_, {}};
        }
        beginRendering(pc, {color}, depth);
        scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
        if (usesRays())
            vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS,
                                    1, &passSet_.set, 0, nullptr);
        if (maps_) maps_->bind(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
        for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend})
            scene_.recordDraws(pc.cmd, layout_, DrawFilter(mode), pipelines_[uint32_t(mode)]);
        endRendering(pc);
    }

    GpuContext& ctx_;
    SceneGpu& scene_;
    SceneFeatures features_;
    RenderSettings settings_;
    ref::Settings ref_;
    bool fp64_ = false;
    bool shadowed_ = false; // some light casts a shadow: shadow rays (prepare)
    static constexpr const char* kPass = "reference_shading";
    std::unique_ptr<ref::ShadowRayScene> rays_;
    std::optional<ShadowMaps> maps_; // --reference-shadows maps
    PassSet passSet_;
    ResourceHandle hdr_, depth_, hdrMsaa_, depthMsaa_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipelines_[3] = {};
};

} // namespace

std::unique_ptr<Renderer> createReferenceRenderer(const RendererCreateInfo& info) {
    return std::make_unique<ReferenceRenderer>(info);
}

} // namespace tp
