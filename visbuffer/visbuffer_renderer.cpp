#include "visbuffer/visbuffer_renderer.h"

#include <algorithm>
#include <cstring>
#include <optional>

#include "core/calibrate/material_fetches.h"
#include "core/calibrate/tiled_work.h"
#include "core/gpu/context.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/readback.h"
#include "core/gpu/resources.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/hybrid_blended.h"
#include "core/passes/meshlet_cull.h"
#include "core/passes/shadow_maps.h"
#include "core/passes/tiled_lighting.h"
#include "visbuffer/blended_ids_pass.h"
#include "visbuffer/draw_table.h"
#include "visbuffer/fragment_bound.h"
#include "visbuffer/raster_merge_pass.h"
#include "visbuffer/raster_pass.h"
#include "visbuffer/vis_settings.h"
#include "visbuffer/visibility_pass.h"

namespace tp {
namespace {

bool hasBlendedDraws(const SceneFeatures& features, const SceneGpu& scene) {
    return features.blended && scene.hasDraws(DrawFilter::Blend);
}

// The settings with their device-dependent defaults resolved: --light-cull, --vis-raster and
// --vis-edges.
vis::Settings resolvedSettings(const RendererCreateInfo& info) {
    vis::Settings s = la::withResolvedCull(vis::readSettings(info.settings), info.ctx,
                                           info.scene.lightsGpu().size(), true);
    s.raster = vis::resolveRaster(info.ctx, s);
    s.edges = vis::resolveEdges(info.ctx, s.edges);
    return s;
}

class VisbufferRenderer final : public Renderer {
  public:
    explicit VisbufferRenderer(const RendererCreateInfo& info)
        : ctx_(info.ctx), scene_(info.scene), features_(info.features),
          vis_(resolvedSettings(info)),
          hasBlended_(hasBlendedDraws(info.features, info.scene)),
          blendInCompute_(hasBlended_ && vis_.blended == vis::Blended::Compute),
          table_(vis::makeDrawTable(info.scene, blendInCompute_)),
          visibility_(info.ctx, info.scene, table_), blendedIds_(info.ctx, info.scene, table_),
          lighting_(info.ctx, info.scene, vis_.debug, vis_.assign.binned(),
                    vis_.assign.slicesOrZero(), la::binsOnGpu(info.ctx, vis_.assign.bin),
                    vis_.manyViews),
          blended_(info.ctx, info.scene) {
        lighting_.setGroup(vis_.tileGroup);
    }

    void plan(FrameGraph& graph) override {
        checkDevice();
        const uint32_t samples = vis_.sampling.samples;
        lt_.grid = la::makeTileGrid(graph.width(), graph.height(), vis_.assign.tile);
        lt_.hdrFormat = vis_.hdr == HdrStorage::Fp16 ? VK_FORMAT_R16G16B16A16_SFLOAT
                                                     : VK_FORMAT_R32G32B32A32_SFLOAT;
        lt_.hdr = graph.createImage(
            "hdr", {lt_.hdrFormat, 0, 0, VK_SAMPLE_COUNT_1_BIT, "linear radiance (resolved)"});
        depth_ = graph.createImage(
            "depth", {VK_FORMAT_D32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                      samples > 1 ? "depth (resolved: sample 0)" : "visibility depth"});
        // The hybrid forward pass blends into per-sample radiance under MSAA; the compute
        // composite blends each sample before the resolve averages them.
        if (hasBlended_ && !blendInCompute_ && samples > 1)
            lt_.hdrMsaa =
                graph.createImage("hdr_msaa", {lt_.hdrFormat, 0, 0, VkSampleCountFlagBits(samples),
                                               "per-sample radiance (blended under MSAA)"});
        lt_.tileStats =
            graph.createBuffer("tile_stats", uint64_t(lt_.grid.count()) * 16,
                               "per tile: lights, transparent lights, edge pixels, overflow");
        if (hasBlended_)
            blended_.planLists(graph, lighting_, lt_, vis_.assign.binned(), slices(),
                               !blendInCompute_, // slice rows: the forward pass's only
                               vis_.manyViews, blendInCompute_);
        if (vis_.debug)
            lt_.debug = graph.createImage(
                "debug_edge_rm", {VK_FORMAT_R32G32B32A32_SFLOAT, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                  "debug: edge mask, roughness, metallic"});
        // Every opaque and masked draw's meshlets, culled for the visibility pass; each
        // command carries its meshlet's first triangle for the ids (visibility_pass.h).
        passes::MeshletCull* cull =
            passes::planOpaqueCull(cull_, ctx_, scene_, graph, vis_.cullGeometry, true);
        // --vis-raster compute|hybrid: the compute rasterizer's passes, its samples into the
        // visibility pass's targets (raster_pass.h, raster_merge_pass.h).
        using Draws = vis::VisibilityPass::Draws;
        ids_ = visibility_.createTargets(graph, samples, depth_);
        if (vis_.raster == vis::Raster::Hardware) {
            visibility_.plan(graph, ids_, cull, Draws::All, false, vis_.debug);
        } else {
            const bool hybrid = vis_.raster == vis::Raster::Hybrid;
            // It reads one phase's kept meshlets: occlusion's late phase is not wired to it.
            if (cull && cull->occlusion())
                throw RendererError("--vis-raster compute|hybrid does not take --cull-geometry "
                                    "full yet; use --cull-geometry none or frustum");
            raster_.emplace(ctx_, scene_, table_, hybrid);
            const vis::RasterTargets raster = raster_->plan(graph, samples, cull);
            merge_.emplace(ctx_, scene_);
            // At 1x the samples are the targets' first contents (the seed), the hardware's
            // draws then test against them; under MSAA they are merged after those draws.
            const bool seeded = merge_->planSeed(graph, samples, ids_, raster);
            visibility_.plan(graph, ids_, cull, hybrid ? Draws::Masked : Draws::None, seeded);
            merge_->plan(graph, samples, ids_, depth_, raster);
        }
        // The blended depth bounds: recorded by the blended lists' fragments where those are
        // the same fragments (docs/visbuffer.md), else by the library pass's own draw.
        ResourceHandle bounds;
        if (hasBlended_) {
            la::BlendedBoundsConfig b{lt_.grid, ids_.depth, samples, vis_.sampling.perSample(),
                                      vis_.sampling.perPixelUnderMsaa()};
            b.drawnElsewhere = blendInCompute_ && b.fusable();
            bounds = blended_.planBounds(graph, b);
            if (b.drawnElsewhere) blendedIds_.recordBounds(bounds, b);
        }
        if (blendInCompute_)
            lists_ = blendedIds_.plan(graph, samples, ids_.depth, vis_.blendedCapacityPercent,
                                      vis_.blendedCapacityPercent == 0 ? fragmentBound() : 0,
                                      vis_.manyViews, vis_.blendedSeen);
        // Static per scene and configuration, like the light candidates: made now, so the
        // surface source can name it.
        drawBuffer_ = createBufferWithData(
            ctx_, table_.rows.data(), table_.rows.size() * sizeof(gpu::VisDraw),
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
            {graph.owner(), "", "visibility_draws",
             "per draw an id names: first index, vertex offset, material"});
        // The resolve samples every shadowed light's map: the atlas, rendered before it.
        shadows_.emplace(ctx_, scene_, ShadowMaps::Residency::Atlas, vis_.cullGeometry,
                         vis_.shadowRaster);
        shadows_->plan(graph); // shadow_maps, with --shadows
        lt_.shadows = &*shadows_;
        lighting_.plan(graph, surfaceSource(), lt_, false, blended_.sliceRows(), bounds);
        if (hasBlended_ && !blendInCompute_)
            blended_.planForward(graph,
                                 {lt_.grid, samples, vis_.sampling.perPixelUnderMsaa(), lt_.hdr,
                                  lt_.hdrMsaa, ids_.depth, lt_.transparentLists, bounds,
                                  lt_.hdrFormat, &*shadows_},
                                 slices());
        graph.exportResource("hdr", lt_.hdr);
        graph.exportResource("depth", depth_);
        graph.exportResource("tile_stats", lt_.tileStats);
        if (hasBlended_) graph.exportResource("blended_bounds", bounds);
        if (blendInCompute_) graph.exportResource("blended_list_counters", lists_.counters);
        if (vis_.debug) graph.exportResource("debug_edge_rm", lt_.debug);
        // --debug: each pixel's blended list (read by the tests beside the edge mask).
        if (vis_.debug && blendInCompute_) graph.exportResource("blended_heads", lists_.heads);
        if (vis_.debug && samples == 1) graph.exportResource("visibility_ids", ids_.ids);
    }

    void prepare(FrameGraph& graph) override {
        if (cull_) cull_->prepare(graph);
        if (raster_) raster_->prepare(graph);
        visibility_.prepare(graph);
        if (merge_) merge_->prepare(graph);
        shadows_->prepare(graph); // its set layout, before the passes sampling it
        lighting_.prepare(graph);
        if (hasBlended_) blended_.prepare(graph, lighting_);
        if (blendInCompute_) blendedIds_.prepare(graph);
    }

    // The ids, the blended draws (back to front) and the resolve are recorded from the scene's
    // current view and lights; what the plan derived from them is recomputed here on the CPU
    // and uploaded (docs/visbuffer.md, "Many views"): the tiled pass's binned candidates, the
    // transparent lists' offsets, and (--vis-blended compute) the draw table's blended rows in
    // the new back-to-front order and the fragment pool's bound.
    bool updateView(FrameGraph& graph) override {
        if (shadows_->stale()) return false; // other shadowed lights or map sizes
        if (!lighting_.updateView(graph)) return false;
        if (hasBlended_ && !blended_.updateLists(lighting_, lt_)) return false;
        if (!blendInCompute_) return true;
        // Many views: the pool is checked after the frames instead (overflowed), from what the
        // view met, not from its bound (which costs milliseconds a view on the CPU).
        if (!vis_.manyViews && vis_.blendedCapacityPercent == 0 &&
            !blendedIds_.fits(fragmentBound()))
            return false;
        // The blended draws' rows follow their back-to-front order, which most new views keep:
        // the buffer is written only when a row moved (a submission and a wait saved a view).
        vis::DrawTable next = vis::makeDrawTable(scene_, true);
        const bool moved = next.rows.size() != table_.rows.size() ||
                           std::memcmp(next.rows.data(), table_.rows.data(),
                                       next.rows.size() * sizeof(gpu::VisDraw)) != 0;
        table_ = std::move(next); // the passes hold it by reference
        if (moved)
            uploadBufferData(ctx_, drawBuffer_, table_.rows.data(),
                             table_.rows.size() * sizeof(gpu::VisDraw));
        return true;
    }

    void collectStats(FrameGraph& graph) override {
        lighting_.collect(graph); // GPU binning: the frame's layout
        if (hasBlended_ && lighting_.gpuBinning()) lt_.listOffsets = lighting_.listOffsets();
        std::vector<uint8_t> raw = readbackBuffer(ctx_, graph.buffer(lt_.tileStats));
        tileStats_.assign(raw.size() / 4, 0);
        std::memcpy(tileStats_.data(), raw.data(), tileStats_.size() * 4);
        if (blendInCompute_) {
            raw = readbackBuffer(ctx_, graph.buffer(lists_.counters));
            std::memcpy(blendCounters_, raw.data(), sizeof(blendCounters_));
        }
        if (cull_) cull_->collect(graph);
        if (raster_) raster_->collect(graph);
        if (shadows_) shadows_->collect(graph);
    }

    // Many views, derived pool: a view that dropped blended fragments is rendered again with a
    // pool twice what it met (RendererSession; docs/visbuffer.md, "Many views").
    // GPU binning: the view needed more than the plan's candidates or transparent lists hold
    // (TiledLighting::overflowed). Both read, so one replan grows both.
    bool overflowed(FrameGraph& graph) override {
        const bool pool = blendInCompute_ && vis_.manyViews && vis_.blendedCapacityPercent == 0 &&
                          blendedIds_.overflowed(graph);
        const bool lists = lighting_.overflowed(graph);
        return pool || lists;
    }
    std::map<std::string, uint64_t> capacityHints() const override {
        return {{vis::kSeenFragments, blendedIds_.grownNeed()}};
    }

    std::vector<DebugImage> debugImages(FrameGraph& graph) override;
    RendererStats stats() const override;
    PassOpWork textureWork() const;
    // The resolve samples a material's textures in one walk of the scene's array (vis_read.glsl):
    // on a CPU device, where every sample site runs in every lane. One decision for the shader's
    // constant and the fetch count.
    bool oneTextureWalk() const { return ctx_.isCpuDevice(); }

  private:
    uint32_t slices() const { return vis_.assign.slicesOrZero(); }
    // The blended fragments the current view can make (fragment_bound.h; many views: the
    // bound clipped to the near plane, computed again for every view).
    uint64_t fragmentBound() const {
        return vis::viewFragmentBound(scene_, table_.blended, vis_.width, vis_.height,
                                      vis_.sampling.samples);
    }
    // --vis-derivatives on this device (TP_VIS_DERIVATIVES_*).
    uint32_t derivativesMode() const {
        return vis::resolveDerivatives(vis_.derivatives);
    }
    void checkDevice() const;
    void addBlendedListStats(RendererStats& s) const;

    // The ids (and depth) as tiled lighting's surface source, with the index buffer and the
    // draw table the reader fetches triangles through.
    SurfaceSource surfaceSource() const {
        SurfaceSource s;
        s.shaderFamily = blendInCompute_ ? "vis_tiled_blend" : "vis_tiled";
        s.attributes = {{ids_.ids, Use::Sampled, TP_VIS_BINDING_IDS}};
        s.depth = ids_.depth;
        s.samples = vis_.sampling.samples;
        s.everySample = vis_.sampling.perSample();
        s.constants = {{TP_VIS_SPEC_TRIANGLE_BITS, table_.triangleBits},
                       {TP_VIS_SPEC_DERIVATIVES, derivativesMode()},
                       {TP_VIS_SPEC_ONE_TEXTURE_WALK, oneTextureWalk() ? 1u : 0u},
                       {TP_VIS_SPEC_IDS_BY_DEPTH, visibility_.idsByDepth() ? 1u : 0u},
                       {TP_VIS_SPEC_SPLIT_EDGES, vis_.splitEdges() ? 1u : 0u}};
        s.buffers = {{TP_VIS_BINDING_INDICES, scene_.indexBuffer()},
                     {TP_VIS_BINDING_DRAWS, drawBuffer_.buffer}};
        if (blendInCompute_) {
            s.attributes.push_back({lists_.heads, Use::StorageRead, TP_VIS_BINDING_BLEND_HEADS});
            s.attributes.push_back({lists_.nodes, Use::StorageRead, TP_VIS_BINDING_BLEND_NODES});
            // The resolve records the longest list it composited.
            s.attributes.push_back(
                {lists_.counters, Use::StorageWrite, TP_VIS_BINDING_BLEND_COUNTERS});
        }
        // The blended fragments' budget guards lavapipe's loop limit (tiled_lighting.h), a CPU
        // device's: a GPU keeps the batches its opaque surfaces get.
        s.evaluationsPerPixel = vis_.evaluationsPerPixel(blendInCompute_ && ctx_.isCpuDevice());
        return s;
    }

    GpuContext& ctx_;
    SceneGpu& scene_;
    SceneFeatures features_;
    vis::Settings vis_; // the settings, typed once (vis_settings.h)
    bool hasBlended_ = false;
    bool blendInCompute_ = false; // --vis-blended compute in a scene with blended draws
    vis::DrawTable table_;
    std::optional<passes::MeshletCull> cull_; // --cull-geometry frustum: meshlet_cull
    std::optional<vis::RasterPass> raster_;   // --vis-raster compute|hybrid
    std::optional<vis::RasterMergePass> merge_; // its samples into the visibility targets
    vis::VisibilityPass visibility_;
    vis::BlendedIdsPass blendedIds_; // --vis-blended compute
    vis::BlendedListTargets lists_;
    uint32_t blendCounters_[TP_VIS_BLEND_COUNTER_WORDS] = {};
    std::optional<ShadowMaps> shadows_; // the atlas (shadow_maps) with --shadows
    TiledLighting lighting_;
    HybridBlended blended_; // blended scenes: lists, depth bounds, the forward pass
    TiledLightingTargets lt_;
    vis::VisibilityTargets ids_;
    ResourceHandle depth_;
    Buffer drawBuffer_;
    std::vector<uint32_t> tileStats_; // uvec4 per tile
};

// One line for a device that cannot run this pipeline, before any image is made.
void VisbufferRenderer::checkDevice() const {
    const uint32_t samples = vis_.sampling.samples;
    auto refuse = [&](const std::string& why) {
        throw RendererError("visbuffer: " + ctx_.info.name + " " + why);
    };
    if (!ctx_.caps.geometryShader)
        refuse("lacks geometryShader, which a fragment shader's gl_PrimitiveID needs");
    if (blendInCompute_ && !ctx_.caps.fragmentStoresAndAtomics)
        refuse("lacks fragmentStoresAndAtomics, which the blended fragment lists need; use "
               "--vis-blended forward");
    // The tiled pass writes per-sample radiance as a multisample storage image.
    if (hasBlended_ && !blendInCompute_ && samples > 1 && !ctx_.caps.storageImageMultisample)
        refuse("lacks shaderStorageImageMultisample, which blended surfaces under --msaa " +
               std::to_string(samples) + " need; use --msaa 1");
}

std::vector<DebugImage> VisbufferRenderer::debugImages(FrameGraph& graph) {
    std::vector<DebugImage> out;
    appendTiledLightingDebug(ctx_, graph, lt_, tileStats_, hasBlended_ ? &blended_ : nullptr, out);
    // The ids themselves (1x: exported with --debug), each pixel's id in r: what compares one
    // rasterizer's ids with another's (--vis-raster; docs/visbuffer.md).
    if (vis_.debug && vis_.sampling.samples == 1)
        out.push_back({"visibility_ids", readbackColor(ctx_, graph.image(ids_.ids)), false});
    return out;
}

// The blended fragment lists' counters (--vis-blended compute): what the pool met, held and
// dropped, and the longest list one pixel composited against the budget its batches assume.
void VisbufferRenderer::addBlendedListStats(RendererStats& s) const {
    const double met = blendCounters_[TP_VIS_BLEND_APPENDED];
    const double pixels = double(vis_.width) * vis_.height;
    s.counters.push_back({"blended_fragments", met});
    s.counters.push_back({"blended_fragments_per_pixel", pixels > 0 ? met / pixels : 0.0});
    s.counters.push_back({"blended_list_capacity", double(lists_.capacity)});
    s.counters.push_back({"blended_fragments_dropped", double(blendCounters_[TP_VIS_BLEND_DROPPED])});
    s.counters.push_back(
        {"blended_fragments_per_pixel_max", double(blendCounters_[TP_VIS_BLEND_MAX_DEPTH])});
    s.leftOut.push_back({"transparent forward pass and per-sample radiance",
                         "--vis-blended compute: blended fragments composited in the resolve"});
}

RendererStats VisbufferRenderer::stats() const {
    RendererStats s;
    if (shadows_) s.counters = shadows_->counters(); // none without --shadows
    const uint32_t samples = vis_.sampling.samples;
    s.counters.push_back({"visibility_bytes_per_sample", 4.0}); // fp32 id, beside depth
    s.counters.push_back({"vis_raster_mode", // --vis-raster, resolved
                          vis_.raster == vis::Raster::Hybrid    ? 2.0
                          : vis_.raster == vis::Raster::Compute ? 1.0
                                                                : 0.0});
    // --vis-edges, resolved: 1 where the resolve split its edges (only when it has them to split:
    // under MSAA at pixel rate with the blended fragments composited in compute).
    if (samples > 1 && !vis_.sampling.perSample() && blendInCompute_)
        s.counters.push_back({"vis_edges_split", vis_.splitEdges() ? 1.0 : 0.0});
    s.counters.push_back({"visibility_draws", double(table_.opaque.size() + table_.masked.size())});
    s.counters.push_back({"visibility_triangle_bits", double(table_.triangleBits)});
    if (cull_) // --cull-geometry frustum: meshlets and triangles, submitted and culled
        for (const auto& c : cull_->counters())
            s.counters.push_back(c);
    if (raster_) { // --vis-raster compute|hybrid: triangles rasterized, listed, culled
        for (const auto& c : raster_->counters())
            s.counters.push_back(c);
        raster_->addWork(s);
    }
    // --vis-derivatives, resolved: 0 analytic, 1 quad fine, 2 quad coarse.
    s.counters.push_back({"uv_derivatives_mode", double(derivativesMode())});
    s.counters.push_back({"hdr_storage_bits_per_channel", // --hdr, resolved
                          vis_.hdr == HdrStorage::Fp16 ? 16.0 : 32.0});
    const TileStatTotals t = sumTileStats(tileStats_);
    const double pixels = double(vis_.width) * vis_.height;
    s.counters.push_back({"lights_per_tile_mean", t.meanLights()});
    s.counters.push_back({"lights_per_tile_max", t.maxLights});
    s.counters.push_back({"tiles_over_shared_capacity", t.overflow}); // shaded in batches
    s.counters.push_back({"lighting_batches", double(lighting_.batches())});
    s.counters.push_back({"light_candidates", double(lighting_.candidates())});
    if (vis_.assign.binned())
        s.counters.push_back({"light_binning_on_gpu", lighting_.gpuBinning() ? 1.0 : 0.0});
    s.counters.push_back({"light_cull_all", vis_.assign.binned() ? 0.0 : 1.0}); // resolved
    s.counters.push_back({"edge_pixel_share", pixels > 0 ? t.edges / pixels : 0.0});
    if (samples > 1 && !ctx_.caps.standardSampleLocations)
        s.leftOut.push_back(
            {"exact MSAA sample positions",
             "device reports non-standard sample locations: samples use the standard ones"});
    if (!hasBlended_)
        s.leftOut.push_back({"transparent forward pass, light lists and blended depth bounds",
                             "no blended material"});
    else
        blended_.addStats(s, tileStats_, lt_.listOffsets);
    if (blendInCompute_) addBlendedListStats(s);
    if (!vis_.assign.clustered())
        s.leftOut.push_back({"depth slices and their bitmasks", "--light-assign tiled"});
    if (samples == 1) s.leftOut.push_back({"per-sample ids and edge pixels", "MSAA is 1x"});
    // Every pixel with geometry evaluates its tile's list (edge samples under MSAA and the
    // blended layers composited in the same pass left out).
    s.lightWork.push_back({"tiled_lighting", PassLightWork::Base::CoveredPixels, s.counter("lights_per_tile_mean"),
                           false, "lights_per_tile_mean, per pixel with geometry"});
    addTiledWork(s, {"tiled_lighting", t.lights, t.edges, t.meanLights(),
                     double(lighting_.candidates()), samples});
    lighting_.addBinningWork(s);
    s.opWork.push_back(textureWork());
    return s;
}

// The resolve's texture fetches per pixel with geometry. On a CPU device its one texture walk
// (vis_read.glsl, TP_VIS_SPEC_ONE_TEXTURE_WALK) has a sample site per texture of the scene,
// and every site runs in every lane: the fetches made are the scene's texture count, not the
// material's slots. On a GPU a site no lane takes costs nothing: the material's slots.
PassOpWork VisbufferRenderer::textureWork() const {
    if (!oneTextureWalk())
        return materialFetchWork(scene_, "tiled_lighting", {DrawFilter::Opaque, DrawFilter::Mask},
                                 PassLightWork::Base::CoveredPixels);
    const size_t textures = std::max<size_t>(1, scene_.scene().textures.size());
    return {"tiled_lighting",
            PassOpWork::Kind::TextureFetches,
            PassLightWork::Base::CoveredPixels,
            double(textures),
            false,
            "every texture of the scene (" + std::to_string(textures) +
                "), per pixel with geometry: the one texture walk of a CPU device samples each "
                "in every lane"};
}

} // namespace

std::unique_ptr<Renderer> createVisbufferRenderer(const RendererCreateInfo& info) {
    return std::make_unique<VisbufferRenderer>(info);
}

} // namespace tp
