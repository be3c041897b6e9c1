#include "deferred/deferred_renderer.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "core/calibrate/material_fetches.h"
#include "core/calibrate/tiled_work.h"
#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/hybrid_blended.h"
#include "core/passes/meshlet_cull.h"
#include "core/passes/shadow_maps.h"
#include "core/passes/tiled_lighting.h"
#include "deferred/def_settings.h"
#include "deferred/gbuffer_pass.h"
#include "deferred/volume_lighting.h"

namespace tp {
namespace {

class DeferredRenderer final : public Renderer {
  public:
    explicit DeferredRenderer(const RendererCreateInfo& info)
        : ctx_(info.ctx), scene_(info.scene), features_(info.features),
          // auto: binned. Its transparent lists add the ambient term last under binned culling
          // and first under all (docs/deferred.md): another image, and no faster on the H200.
          def_(la::withResolvedCull(def::readSettings(info.settings), info.ctx,
                                    info.scene.lightsGpu().size(), false)),
          gbuffer_(info.ctx, info.scene),
          lighting_(info.ctx, info.scene, def_.debug, def_.assign.binned(),
                    def_.assign.slicesOrZero(), la::binsOnGpu(info.ctx, def_.assign.bin),
                    def_.manyViews),
          volumes_(info.ctx, info.scene, def_.cullGeometry, def_.shadowRaster),
          blended_(info.ctx, info.scene) {
        lighting_.setGroup(def_.tileGroup);
    }

    void plan(FrameGraph& graph) override {
        t_.layout = planGBufferLayout(ctx_, features_, def_.gbuffer, def_.sampling.samples);
        t_.sampleRateGBuffer = def_.sampling.shading == MsaaShading::Sample;
        t_.clearGBuffer = def_.debug;
        // The lighting group is 8 x 8 or 16 x 16 invocations (--tile-group, at most the tile),
        // each covering (tileSize / edge)^2 pixels: the tile knob's values (8, 16, 32) are all
        // multiples of the edge.
        t_.grid = la::makeTileGrid(graph.width(), graph.height(), def_.assign.tile);
        const uint32_t tiles = t_.grid.count();
        // --hdr: fp32 keeps the light sum exact to readback; fp16 halves the bytes (Forward+'s
        // format).
        t_.hdrFormat = def_.hdr == def::Hdr::Fp16 ? VK_FORMAT_R16G16B16A16_SFLOAT
                                                  : VK_FORMAT_R32G32B32A32_SFLOAT;
        t_.hdr = graph.createImage(
            "hdr", {t_.hdrFormat, 0, 0, VK_SAMPLE_COUNT_1_BIT, "linear radiance (resolved)"});
        t_.depth = graph.createImage("depth",
                                     {VK_FORMAT_D32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                      t_.msaa() ? "depth (resolved: sample 0)" : "G-buffer depth"});
        hasBlended_ = features_.blended && scene_.hasDraws(DrawFilter::Blend);
        // The tiled pass writes per-sample radiance as a multisample storage image: refuse a
        // device without them in one line rather than meet a validation error.
        if (hasBlended_ && t_.msaa() && !ctx_.caps.storageImageMultisample)
            throw RendererError("deferred: blended surfaces under --msaa " +
                                std::to_string(def_.sampling.samples) +
                                " need multisample storage images, which " + ctx_.info.name +
                                " lacks (shaderStorageImageMultisample); use --msaa 1");
        if (hasBlended_ && t_.msaa())
            t_.hdrMsaa = graph.createImage(
                "hdr_msaa", {t_.hdrFormat, 0, 0, VkSampleCountFlagBits(def_.sampling.samples),
                             "per-sample radiance (blended under MSAA)"});
        // Volumes lighting of an opaque-only scene runs no tile pass at all.
        const bool tilePass = !useVolumes() || hasBlended_;
        if (tilePass)
            t_.tileStats =
                graph.createBuffer("tile_stats", uint64_t(tiles) * 16,
                                   "per tile: lights, transparent lights, edge pixels, overflow");
        if (hasBlended_) planBlendedLists(graph);
        if (def_.debug && !useVolumes())
            t_.debug = graph.createImage(
                "debug_edge_rm", {VK_FORMAT_R32G32B32A32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                  "debug: edge mask, roughness, metallic"});
        // The opaque and masked draws' meshlets, culled for the G-buffer pass; the blended
        // forward pass draws its meshes whole, back to front.
        gbuffer_.plan(graph, t_,
                      passes::planOpaqueCull(cull_, ctx_, scene_, graph, def_.cullGeometry),
                      def::prepassOn(ctx_, def_));
        // Blended depth bounds: the fragments of the blended pass at the rate it shades them
        // (per pixel or per sample under MSAA), before the transparent lists are culled against
        // them.
        ResourceHandle bounds;
        if (hasBlended_)
            bounds = blended_.planBounds(graph, {t_.grid, t_.gbufferDepth, t_.layout.samples,
                                                 t_.msaa() && !t_.blendedPerPixel(),
                                                 t_.blendedPerPixel()});
        if (!useVolumes()) { // tiled lighting samples every shadowed light's map: the atlas
            shadows_.emplace(ctx_, scene_, ShadowMaps::Residency::Atlas, def_.cullGeometry,
                             def_.shadowRaster);
            shadows_->plan(graph); // shadow_maps, with --shadows
        }
        if (tilePass)
            lighting_.plan(graph, surfaceSource(), lightingTargets(), useVolumes(),
                           blended_.sliceRows(), bounds);
        if (useVolumes()) volumes_.plan(graph, t_);
        if (hasBlended_)
            blended_.planForward(graph,
                                 {t_.grid, t_.layout.samples, t_.blendedPerPixel(), t_.hdr,
                                  t_.hdrMsaa, t_.gbufferDepth, t_.transparentLists, bounds,
                                  t_.hdrFormat, atlas()},
                                 slices());
        exportOutputs(graph, tilePass, bounds);
    }

    // Blended scenes: the transparent light lists tiled lighting writes and the blended pass
    // reads (and, clustered, their slice rows; volumes lighting keeps the plain lists).
    void planBlendedLists(FrameGraph& graph) {
        TiledLightingTargets lt = lightingTargets();
        blended_.planLists(graph, lighting_, lt, binned(), slices(), !useVolumes(),
                           def_.manyViews);
        t_.transparentLists = lt.transparentLists;
        t_.listOffsets = std::move(lt.listOffsets);
    }

    void exportOutputs(FrameGraph& graph, bool tilePass, ResourceHandle bounds) {
        graph.exportResource("hdr", t_.hdr);
        graph.exportResource("depth", t_.depth);
        if (tilePass) graph.exportResource("tile_stats", t_.tileStats);
        if (hasBlended_) graph.exportResource("blended_bounds", bounds);
        if (hasBlended_)
            graph.exportResource("transparent_lists", t_.transparentLists); // tests: their order
        if (t_.edgeMask.valid())
            graph.exportResource("volume_edge_mask", t_.edgeMask); // edge share
        if (def_.debug) {
            if (t_.debug.valid()) graph.exportResource("debug_edge_rm", t_.debug);
            if (!t_.msaa())
                graph.exportResource("gbuffer_base", t_.gbuffer[0]); // readback: 1x only
        }
    }

    void prepare(FrameGraph& graph) override {
        if (cull_) cull_->prepare(graph);
        gbuffer_.prepare(graph);
        if (shadows_) shadows_->prepare(graph); // its set layout, before the passes sampling it
        if (t_.tileStats.valid()) lighting_.prepare(graph);
        if (useVolumes()) volumes_.prepare(graph);
        if (hasBlended_) blended_.prepare(graph, lighting_);
    }

    // The G-buffer, the volumes and the blended draws (back to front) are recorded from the
    // scene's current view and lights; what the plan derived from them is the tiled pass's
    // binned candidates and the transparent lists' offsets, recomputed here on the CPU and
    // uploaded (docs/deferred.md, "Many views").
    bool updateView(FrameGraph& graph) override {
        if (useVolumes() && volumes_.stale()) return false; // other shadowed lights or map sizes
        if (shadows_ && shadows_->stale()) return false;
        if (!t_.tileStats.valid()) return true; // volumes, opaque only: nothing derived
        if (!lighting_.updateView(graph)) return false;
        if (!hasBlended_) return true;
        TiledLightingTargets lt = lightingTargets();
        if (!blended_.updateLists(lighting_, lt)) return false;
        t_.listOffsets = std::move(lt.listOffsets);
        return true;
    }

    // GPU binning: the view needed more than the plan's candidates or transparent lists hold
    // (counted on the GPU, read after the frames); the session plans again for it.
    bool overflowed(FrameGraph& graph) override {
        return t_.tileStats.valid() && lighting_.overflowed(graph);
    }

    void collectStats(FrameGraph& graph) override {
        if (t_.tileStats.valid()) {
            lighting_.collect(graph); // GPU binning: the frame's layout
            if (hasBlended_ && lighting_.gpuBinning()) t_.listOffsets = lighting_.listOffsets();
            std::vector<uint8_t> raw = readbackBuffer(ctx_, graph.buffer(t_.tileStats));
            tileStats_.assign(raw.size() / 4, 0);
            std::memcpy(tileStats_.data(), raw.data(), tileStats_.size() * 4);
        }
        if (t_.edgeMask.valid()) {
            ImageRGBA mask = readbackColor(ctx_, graph.image(t_.edgeMask));
            volumeEdges_ = 0;
            for (size_t i = 0; i < mask.pixelCount(); ++i)
                volumeEdges_ += mask.rgba[i * 4] > 0.5f ? 1 : 0;
        }
        if (cull_) cull_->collect(graph);
        if (shadows_) shadows_->collect(graph);
        if (useVolumes()) volumes_.collectShadows(graph);
    }

    std::vector<DebugImage> debugImages(FrameGraph& graph) override;
    RendererStats stats() const override;

  private:
    void addLightWork(RendererStats& s) const;
    bool binned() const { return def_.assign.binned(); }

    // The G-buffer as tiled lighting's surface source: its colour targets at the bindings
    // gbuffer_read.glsl declares, in layout.colors order.
    SurfaceSource surfaceSource() const {
        const uint32_t bindings[] = {TP_DEF_BINDING_BASE, TP_DEF_BINDING_NORMAL,
                                     TP_DEF_BINDING_ROUGH_METAL, TP_DEF_BINDING_EMISSIVE};
        SurfaceSource s;
        s.shaderFamily = "deferred_tiled";
        for (size_t i = 0; i < t_.gbuffer.size(); ++i)
            s.attributes.push_back({t_.gbuffer[i], Use::Sampled, bindings[i]});
        s.depth = t_.gbufferDepth;
        s.samples = t_.layout.samples;
        s.emissive = t_.layout.emissive;
        s.everySample = t_.sampleRateGBuffer;
        s.constants = {{TP_DEF_SPEC_WIDE, t_.layout.wide ? 1u : 0u}};
        return s;
    }

    TiledLightingTargets lightingTargets() const {
        return {t_.grid,      t_.hdr,        t_.hdrMsaa,
                t_.hdrFormat, t_.tileStats,  t_.transparentLists,
                t_.debug,     t_.listOffsets, atlas()};
    }
    // The shadow atlas tiled lighting and the blended pass sample (null: volumes lighting).
    const ShadowMaps* atlas() const { return shadows_ ? &*shadows_ : nullptr; }

    GpuContext& ctx_;
    SceneGpu& scene_;
    SceneFeatures features_;
    def::Settings def_; // the settings, typed once (def_settings.h)
    bool useVolumes() const { return def_.lighting == def::Lighting::Volumes; }
    // --light-assign clustered: depth slices; 0 when tiled.
    uint32_t slices() const { return def_.assign.slicesOrZero(); }
    DeferredTargets t_;
    bool hasBlended_ = false;
    std::optional<passes::MeshletCull> cull_; // --cull-geometry frustum: meshlet_cull
    uint64_t volumeEdges_ = 0; // edge pixels found by the volumes base pass (MSAA)
    GBufferPass gbuffer_;
    std::optional<ShadowMaps> shadows_; // tiled lighting: the atlas (shadow_maps) with --shadows
    TiledLighting lighting_;
    VolumeLighting volumes_;
    HybridBlended blended_;           // blended scenes: lists, depth bounds, the forward pass
    std::vector<uint32_t> tileStats_; // uvec4 per tile
};

std::vector<DebugImage> DeferredRenderer::debugImages(FrameGraph& graph) {
    std::vector<DebugImage> out;
    // RGBA8_SRGB reads back as the raw encoded bytes / 255: already display sRGB.
    if (!t_.msaa())
        out.push_back(
            {"gbuffer_base_color", readbackColor(ctx_, graph.image(t_.gbuffer[0])), true});
    if (useVolumes()) { // no tile pass shaded: the edge mask is the base pass's (MSAA only)
        if (t_.edgeMask.valid())
            out.push_back({"edge_mask", readbackColor(ctx_, graph.image(t_.edgeMask)), true});
        return out;
    }
    appendTiledLightingDebug(ctx_, graph, lightingTargets(), tileStats_, hasBlended_ ? &blended_ : nullptr, out);
    return out;
}

RendererStats DeferredRenderer::stats() const {
    RendererStats s;
    if (shadows_) s.counters = shadows_->counters(); // none without --shadows
    const uint32_t samples = t_.layout.samples;
    s.counters.push_back({"gbuffer_bytes_per_sample", double(t_.layout.bytesPerSample())});
    s.counters.push_back({"gbuffer_bytes_per_pixel", double(t_.layout.bytesPerSample() * samples)});
    s.counters.push_back({"gbuffer_prepass", // --gbuffer-prepass, resolved
                          def::prepassOn(ctx_, def_) ? 1.0 : 0.0});
    s.counters.push_back({"hdr_storage_bits_per_channel", // --hdr, resolved
                          def_.hdr == def::Hdr::Fp16 ? 16.0 : 32.0});
    if (cull_) // --cull-geometry frustum: meshlets and triangles, submitted and culled
        for (const auto& c : cull_->counters())
            s.counters.push_back(c);
    const TileStatTotals totals = sumTileStats(tileStats_);
    double edges = totals.edges;
    double pixels = double(def_.width) * def_.height;
    if (useVolumes()) {
        edges = double(volumeEdges_);
        s.counters.push_back({"light_volume_draws", double(scene_.lightCount())});
        for (const auto& c : volumes_.shadowCounters()) s.counters.push_back(c); // --shadows
        s.leftOut.push_back(
            {"lights per tile (statistics, heat map)", "volumes lighting has no opaque tiles"});
    } else {
        s.counters.push_back({"lights_per_tile_mean", totals.meanLights()});
        s.counters.push_back({"lights_per_tile_max", totals.maxLights});
        s.counters.push_back({"tiles_over_shared_capacity",
                              totals.overflow}); // shaded with every light, none dropped
    }
    if (t_.tileStats.valid()) {
        // Light-vs-tile tests of the tiled pass's culling (binned: the candidates).
        s.counters.push_back({"light_candidates", double(lighting_.candidates())});
        if (binned()) // --light-bin, resolved
            s.counters.push_back({"light_binning_on_gpu", lighting_.gpuBinning() ? 1.0 : 0.0});
        s.counters.push_back({"light_cull_all", binned() ? 0.0 : 1.0}); // --light-cull, resolved
    }
    s.counters.push_back({"edge_pixel_share", pixels > 0 ? edges / pixels : 0.0});
    if (samples > 1 && !ctx_.caps.standardSampleLocations)
        s.leftOut.push_back(
            {"exact MSAA sample positions",
             "device reports non-standard sample locations: edge samples use the standard ones"});
    if (!t_.layout.emissive)
        s.leftOut.push_back({"emissive G-buffer target", "no emissive material"});
    if (!hasBlended_)
        s.leftOut.push_back({"transparent forward pass, light lists and blended depth bounds",
                             "no blended material"});
    const bool clustered = def_.assign.clustered();
    if (!clustered)
        s.leftOut.push_back({"depth slices and their bitmasks", "--light-assign tiled"});
    else if (useVolumes())
        s.leftOut.push_back({"depth slices and their bitmasks",
                             "volumes lighting draws each light's volume; "
                             "--light-assign applies to tiled lighting"});
    else if (!hasBlended_)
        s.leftOut.push_back({"slice rows over the transparent lists", "no blended material"});
    if (hasBlended_) blended_.addStats(s, tileStats_, t_.listOffsets);
    if (samples == 1) s.leftOut.push_back({"per-sample targets and edge mask", "MSAA is 1x"});
    if (samples > 1)
        s.counters.push_back({"gbuffer_material_per_sample", t_.sampleRateGBuffer ? 1.0 : 0.0});
    addLightWork(s);
    if (!useVolumes()) // MSAA edge samples, shared atomics, light-vs-tile tests
        addTiledWork(s, {"tiled_lighting", totals.lights, totals.edges, totals.meanLights(),
                         double(lighting_.candidates()), samples});
    lighting_.addBinningWork(s);
    return s;
}

// Tiled: every pixel with geometry evaluates its tile's list (edge samples under MSAA left
// out); volumes: every fragment of a light's volume evaluates that light.
void DeferredRenderer::addLightWork(RendererStats& s) const {
    using Base = PassLightWork::Base;
    if (useVolumes())
        s.lightWork.push_back({"volume_lights", Base::Fragments, 1.0, true, "one light per volume fragment"});
    else
        s.lightWork.push_back({"tiled_lighting", Base::CoveredPixels, s.counter("lights_per_tile_mean"), false,
                               "lights_per_tile_mean, per pixel with geometry"});
    if (useVolumes() && volumes_.shadowPass()) // masked shadow-map draws run fragments too
        s.lightWork.push_back({"volume_shadowed_lights", Base::Fragments, 1.0, false,
                               "one light per volume fragment (and per masked shadow-map fragment)"});
    s.opWork.push_back(materialFetchWork(scene_, "gbuffer", {DrawFilter::Opaque, DrawFilter::Mask},
                                         Base::Fragments));
    if (hasBlended_)
        s.opWork.push_back(
            materialFetchWork(scene_, "transparent_forward", {DrawFilter::Blend}, Base::Fragments));
    if (hasBlended_)
        s.lightWork.push_back({"transparent_forward", Base::Fragments,
                               s.counter("transparent_lights_per_nonempty_tile_mean"), false,
                               "transparent_lights_per_nonempty_tile_mean, per fragment"});
}

} // namespace

std::unique_ptr<Renderer> createDeferredRenderer(const RendererCreateInfo& info) {
    return std::make_unique<DeferredRenderer>(info);
}

} // namespace tp
