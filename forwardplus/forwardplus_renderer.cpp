#include "forwardplus/forwardplus_renderer.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>
#include <string>

#include "core/calibrate/material_fetches.h"
#include "core/gpu/context.h"
#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpu/rendering.h"
#include "core/gpu/resources.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/image/difference.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/tile_grid.h"
#include "core/passes/blended_bounds.h"
#include "core/passes/depth_prepass.h"
#include "core/passes/light_binning.h"
#include "core/passes/meshlet_cull.h"
#include "core/passes/shadow_maps.h"
#include "core/renderer/msaa_knob.h"
#include "forwardplus/forward_shading.h"
#include "forwardplus/forwardplus_debug.h"
#include "forwardplus/forwardplus_shared.h"
#include "forwardplus/fp_config.h"
#include "forwardplus/fp_settings.h"
#include "forwardplus/light_culling.h"
#include "forwardplus/light_lists.h"
#include "forwardplus/light_spheres.h"
#include "forwardplus/list_counters.h"
#include "forwardplus/view_bins.h"

namespace tp {
namespace {

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

class ForwardPlusRenderer final : public Renderer {
  public:
    explicit ForwardPlusRenderer(const RendererCreateInfo& info)
        : ctx_(info.ctx), scene_(info.scene), features_(info.features),
          fp_(la::withResolvedCull(fp::readSettings(info.settings), info.ctx,
                                   info.scene.lightsGpu().size(), true)),
          manyViews_(info.settings.manyViews),
          hdrFormat_(fp_.hdr == HdrStorage::Fp16 ? VK_FORMAT_R16G16B16A16_SFLOAT
                                                 : VK_FORMAT_R32G32B32A32_SFLOAT),
          r_(fp::resolve(ctx_, scene_, features_, fp_)) {
        grid_ = la::makeTileGrid(fp_.width, fp_.height, fp_.assign.tile);
        classes_ = la::classifyLights(scene_.lightsGpu());
        if (boundsLists()) boundLists();
        lists_ = fp::sizeLists(ctx_, {layout(), fp::listsText(fp_.lists), grid_.count(),
                                      fp_.tileCapacity, cap_.slots, r_.numLists});
        culling_.emplace(ctx_, scene_, cullConfig());
        if (r_.blendPass) blendBounds_.emplace(ctx_, scene_);
        // Opaque fragments shaded once at the pixel centre: where their centres are
        // (core/passes/blended_bounds.h, `opaque`).
        if (fp_.sampling.perPixelUnderMsaa()) centreBounds_.emplace(ctx_, scene_);
    }

    void plan(FrameGraph& graph) override {
        const bool msaa = samples() > 1;
        const auto sampleBits = VkSampleCountFlagBits(samples());
        const std::string format = fp_.hdr == HdrStorage::Fp16 ? "RGBA16F" : "RGBA32F";
        hdr_ = graph.createImage("hdr", {hdrFormat_, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                         "linear radiance, resolved (" + format + ")"});
        depth_ =
            graph.createImage("depth", {kDepthFormat, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                        msaa ? "depth (resolved: sample 0)" : "prepass depth"});
        if (msaa) {
            hdrMsaa_ = graph.createImage(
                "hdr_msaa", {hdrFormat_, 0, 0, sampleBits, "per-sample radiance (" + format + ")"});
            depthMsaa_ = graph.createImage(
                "depth_msaa", {kDepthFormat, 0, 0, sampleBits, "per-sample prepass depth"});
        }
        const ResourceHandle depthSrc = msaa ? depthMsaa_ : depth_;

        tiles_ =
            graph.createBuffer("tile_lists", VkDeviceSize(grid_.count()) * sizeof(gpu::FpTileLists),
                               "per tile: list counts, starts, drops, depth bounds");
        indices_ = graph.createBuffer("light_indices", lists_.bytes, lists_.purpose);
        if (layout() == TP_FP_LAYOUT_LINKED)
            counter_ =
                graph.createBuffer("node_counter", 16, "linked lists: node allocation counter");
        if (clustered())
            masks_ =
                graph.createBuffer("cluster_masks", std::max<uint64_t>(cap_.maskWords * 4, 16),
                                   "per tile and depth slice: a bitmask over the tile's list");

        passes::DepthPrepassParams prepass{samples(), scene_.drawList(DrawFilter::Opaque),
                                           scene_.drawList(DrawFilter::Mask)};
        // The opaque and masked draws, culled once per frame for the prepass and
        // forward_opaque alike (the EQUAL test needs the same triangles in both).
        prepass.cull = passes::planOpaqueCull(cull_, ctx_, scene_, graph, fp_.cullGeometry);
        prepass_.emplace(ctx_, scene_, std::move(prepass));
        prepass_->plan(graph, {depthSrc, msaa ? depth_ : ResourceHandle{}});

        if (layout() == TP_FP_LAYOUT_LINKED)
            graph.addPass(
                "node_counter_reset", {{counter_, Use::TransferDst}}, [this](PassContext& pc) {
                    vkCmdFillBuffer(pc.cmd, pc.buffer(counter_).buffer, 0, VK_WHOLE_SIZE, 0);
                });

        if (binning_) binning_->plan(graph); // the candidates the culling reads, every frame
        // Blended depth bounds: the blended shading pass's fragments, before the culling reads
        // them.
        ResourceHandle blendBounds;
        if (r_.blendPass)
            blendBounds =
                blendBounds_->plan(graph, {grid_, depthSrc, samples(), fp_.sampling.perSample(),
                                           fp_.sampling.perPixelUnderMsaa()});
        ResourceHandle centreBounds;
        if (centreBounds_) {
            la::BlendedBoundsConfig centres{grid_, depthSrc, samples(), false, true};
            centres.opaque = true;
            centreBounds = centreBounds_->plan(graph, centres);
        }
        const ResourceHandle spheres = r_.spherePass ? spheres_.plan(graph) : ResourceHandle{};
        culling_->plan(graph, {depthSrc, tiles_, indices_, counter_, masks_, blendBounds, spheres,
                               centreBounds});

        // shadow_maps, if any (its faces culled with --cull-geometry)
        shadows_.emplace(ctx_, scene_, ShadowMaps::Residency::Atlas, fp_.cullGeometry,
                         fp_.shadowRaster);
        shadows_->plan(graph);
        fp::ShadingConfig shadingConfig{fp_.sampling, fp_.assign.tile, layout(), fp_.assign.slices,
                                        r_.twoLists, clustered(), r_.blendPass, r_.subgroupLoop};
        shadingConfig.tilesX = grid_.tilesX;
        shadingConfig.tilesY = grid_.tilesY;
        shading_.emplace(ctx_, scene_, shadingConfig);
        shading_->plan(graph, {hdr_, hdrMsaa_, depth_, depthMsaa_, tiles_, indices_, masks_,
                               hdrFormat_, &*shadows_, cull_ ? &*cull_ : nullptr});
        graph.exportResource("hdr", hdr_);
        graph.exportResource("depth", depth_);
        // Read back after the frame for the statistics, debug images and tests.
        graph.exportResource("fp_tile_lists", tiles_);
        graph.exportResource("fp_light_indices", indices_);
        if (layout() == TP_FP_LAYOUT_LINKED) graph.exportResource("fp_node_counter", counter_);
        if (clustered()) graph.exportResource("fp_cluster_masks", masks_);
        if (r_.blendPass) graph.exportResource("blended_bounds", blendBounds);
    }

    void prepare(FrameGraph& graph) override {
        createParams();
        if (cull_) cull_->prepare(graph);
        prepass_->prepare();
        if (blendBounds_) blendBounds_->prepare(graph);
        if (centreBounds_) centreBounds_->prepare(graph);
        createDescriptors(graph);
        shadows_->prepare(graph);
        shading_->prepare(graph, params_.buffer);
    }

    // A new view (the camera or the lights' positions): its bins on the CPU laid out in the
    // planned lists, fp_params and the shading's lights copy uploaded again; the frame's passes
    // (spheres, binning, culling) recompute the rest. false when the view outgrew the lists'
    // room or the light types changed. With the GPU binning, tiled or clustered, nothing of
    // fp_params follows the view: the frame's light_binning writes the offsets, the runs and
    // the mask rows' offsets, and a view past the room is caught after its frames
    // (overflowed): no readback here.
    bool updateView(FrameGraph&) override {
        if (shadows_->stale()) return false; // other shadowed lights or map sizes
        const la::LightClasses classes = la::classifyLights(scene_.lightsGpu());
        if (classes.directional != classes_.directional || classes.local != classes_.local)
            return false; // fp_params' light classes and the shading's loop are planned
        if (viewOnGpu()) {
            binning_->followView();
            shading_->updateLights();
            return true;
        }
        if (boundsLists()) {
            fp::ViewBins bins = fp::binView(scene_, viewBinning());
            if (!cap_.holds(bins)) return false;
            bins_ = std::move(bins);
        }
        const fp::PackedParams packed = packParams();
        if (packed.bytes.size() != params_.size) return false; // not laid out as planned
        uploadBufferData(ctx_, params_, packed.bytes.data(), packed.bytes.size());
        culling_->setMostTested(mostTested());
        shading_->updateLights();
        return true;
    }

    // --light-bin gpu: the view's lists were cut (more slots than the room, more mask words
    // than the clusters' room, or a run longer than the frame's batches and sort were recorded
    // for); the session plans again, and the plan's sizing run sizes the lists for this view.
    bool overflowed(FrameGraph& graph) override {
        return binning_ && binning_->overflowed(graph, culling_->batchSize());
    }

    void collectStats(FrameGraph& graph) override {
        if (binning_) { // the frame's layout (updateView no longer reads it back)
            la::LightBins frame = binning_->collect(graph);
            bins_.bound = std::move(frame.bound);
            bins_.offsets = std::move(frame.offsets);
            bins_.slots = frame.slots;
            bins_.maxBound = frame.maxBound;
            // The rows the frame laid out (bin_scan_words.comp: the same layout, from the same
            // counts), for the clusters' statistics.
            if (clustered()) bins_.masks = fp::layoutMasks(bins_.bound, fp_.assign.slices);
        }
        std::vector<uint8_t> bytes = readbackBuffer(ctx_, graph.buffer(tiles_));
        tileLists_.resize(grid_.count());
        std::memcpy(tileLists_.data(), bytes.data(), tileLists_.size() * sizeof(gpu::FpTileLists));
        if (layout() == TP_FP_LAYOUT_LINKED) {
            std::vector<uint8_t> c = readbackBuffer(ctx_, graph.buffer(counter_));
            std::memcpy(&nodesUsed_, c.data(), sizeof(uint32_t));
        }
        if (blendBounds_)
            blended_ = la::unpackBlendedBounds(
                readbackBuffer(ctx_, graph.buffer(blendBounds_->buffer())), grid_.count());
        if (clustered()) {
            std::vector<uint8_t> m = readbackBuffer(ctx_, graph.buffer(masks_));
            maskBits_.resize(m.size() / 4);
            std::memcpy(maskBits_.data(), m.data(), maskBits_.size() * 4);
        }
        if (cull_) cull_->collect(graph);
        if (shadows_) shadows_->collect(graph);
        collected_ = true;
    }

    std::vector<DebugImage> debugImages(FrameGraph&) override {
        if (!collected_) return {};
        std::vector<DebugImage> out;
        out.push_back({"lights_per_tile", fp::lightsPerTileHeatMap(grid_, tileLists_, 0), true});
        if (r_.twoLists)
            out.push_back({"lights_per_tile_transparent",
                           fp::lightsPerTileHeatMap(grid_, tileLists_, 1), true});
        out.push_back({"tile_depth_bounds",
                       fp::tileDepthBoundsImage(grid_, tileLists_, scene_.frame().invProj), true});
        return out;
    }

    RendererStats stats() const override {
        RendererStats s;
        if (shadows_) s.counters = shadows_->counters();
        auto add = [&](const std::string& name, double v) { s.counters.push_back({name, v}); };
        add("tile_size", fp_.assign.tile);
        add("tiles", grid_.count());
        add("light_lists", double(r_.numLists));
        add("directional_lights_unculled", double(classes_.directional.size()));
        add("local_lights", double(classes_.local.size()));
        add("hdr_storage_bits_per_channel",
            fp_.hdr == HdrStorage::Fp16 ? 16.0 : 32.0); // --hdr, resolved
        add("light_list_slots", double(lists_.slots));
        add("culling_dispatches",
            double(culling_->dispatches())); // batches of candidates (lavapipe's loop limit)
        add("light_spheres_pass", r_.spherePass ? 1.0 : 0.0);    // --light-spheres, resolved
        add("culling_by_subgroup", r_.subgroupCull ? 1.0 : 0.0); // --cull-by, resolved
        if (cull_) // --cull-geometry frustum: meshlets and triangles, submitted and culled
            for (const auto& c : cull_->counters()) s.counters.push_back(c);
        if (binned()) {
            add("binned_candidates", double(r_.gpuBinning ? bins_.slots : bins_.candidates.size()));
            add("light_binning_on_gpu", r_.gpuBinning ? 1.0 : 0.0); // --light-bin, resolved
        }
        add("light_cull_all", binned() ? 0.0 : 1.0); // --light-cull, resolved
        if (clustered()) {
            add("slices", double(fp_.assign.slices));
            add("cluster_mask_words", double(bins_.masks.words));
            add("light_loop_subgroup",
                r_.subgroupLoop ? 1.0 : 0.0); // 0: lane loop (asked for, or the fallback)
        }
        if (manyViews_ && boundsLists()) {
            add("view_list_slots_needed", double(bins_.slots)); // this view's, of one list kind
            add("view_list_slots_planned", double(cap_.slots)); // the room (kViewHeadroom)
        }
        if (collected_) {
            static const std::vector<uint32_t> none;
            fp::ListCounterInput in{tileLists_, blended_, binned() ? bins_.bound : none,
                                    bins_.masks.offsets, maskBits_};
            in.localLights = classes_.local.size();
            in.slices = fp_.assign.slices;
            in.twoLists = r_.twoLists;
            in.clustered = clustered();
            in.blendPass = r_.blendPass;
            in.linked = layout() == TP_FP_LAYOUT_LINKED;
            in.nodesUsed = nodesUsed_;
            in.poolNodes = lists_.poolNodes;
            fp::addListCounters(s.counters, in);
            fp::addLightWork(s, r_, fp_, classes_.directional.size());
            fp::addCullingWork(s);
        }
        s.opWork.push_back(materialFetchWork(scene_, "forward_opaque",
                                             {DrawFilter::Opaque, DrawFilter::Mask},
                                             PassLightWork::Base::Fragments));
        if (r_.blendPass)
            s.opWork.push_back(materialFetchWork(scene_, "forward_transparent", {DrawFilter::Blend},
                                                 PassLightWork::Base::Fragments));
        if (binning_) binning_->addStats(s, bins_.slots);
        fp::addLeftOut(s, r_, fp_, scene_, features_);
        return s;
    }

  private:
    // Whether the lists' layout follows the view: the compact and linked layouts' bound, binned
    // culling's candidates (fixed, unbinned: nothing to bin).
    bool boundsLists() const { return layout() != TP_FP_LAYOUT_FIXED || binned(); }
    // The GPU binning lays out every view itself: the runs' offsets and, clustered, the mask
    // rows' offsets (GpuBinning::publishWords).
    bool viewOnGpu() const { return r_.gpuBinning; }

    fp::ViewBinning viewBinning() {
        return {grid_, &classes_, binned(), clustered(), fp_.assign.slices, binning_.get()};
    }

    // The conservative tile rectangle of every local light (CPU, per view: updateView bins
    // again), counted per tile: the compact layout's bound; with binned culling also each
    // tile's candidates, in ascending light order. The plan's room: cap_.
    void boundLists() {
        // --light-bin gpu: the frame builds the candidates; a sizing run per view sizes them.
        if (r_.gpuBinning)
            binning_ = std::make_unique<la::GpuBinning>(ctx_, scene_, grid_, classes_.local,
                                                        "forwardplus", manyViews_);
        bins_ = fp::binView(scene_, viewBinning());
        // 32-bit offsets index data[] in fp_params: refuse what they cannot address.
        if (bins_.slots > fp::addressableSlots(viewBinning()))
            throw RendererError(
                "the tile lists need " + std::to_string(bins_.slots) +
                " slots, more than 32-bit offsets address; use a larger --tile, a lower --res or "
                "fewer lights");
        if (clustered()) bins_.masks = fp::sizeMasks(ctx_, bins_.bound, fp_.assign.slices);
        cap_ = fp::planCapacity(bins_, viewBinning(), manyViews_,
                                {ctx_.caps.maxStorageBufferRange, r_.numLists,
                                 layout() == TP_FP_LAYOUT_LINKED});
    }

    // fp_params for the current view, laid out in the planned room (the same bytes every view).
    fp::PackedParams packParams() const {
        fp::ParamsInput in;
        in.grid = grid_;
        in.classes = &classes_;
        in.layout = layout();
        in.binned = binned();
        in.tileOffsets = &bins_.offsets;
        in.candidates = &bins_.candidates;
        in.candidateSlots = binned() ? cap_.slots : 0;
        in.maskOffsets = &bins_.masks.offsets;
        in.tileCapacity = fp_.tileCapacity;
        in.lists = lists_;
        return fp::packParams(ctx_, in);
    }

    void createParams() {
        fp::PackedParams packed = packParams();
        candidateWord_ = packed.candidateWord;
        offsetWord_ = packed.offsetWord;
        maskOffsetWord_ = packed.maskOffsetWord;
        params_ = createBufferWithData(ctx_, packed.bytes.data(), packed.bytes.size(),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       {"forwardplus", "", "fp_params", packed.purpose});
    }

    // The most lights a tile tests: the culling's batches (GPU binning: the longest run it
    // plans, checked after each view).
    uint32_t mostTested() const {
        if (binning_) return binning_->runBound();
        return binned() ? bins_.maxBound : uint32_t(classes_.local.size());
    }

    // The culling pass's configuration: what its shader variant, batches and dispatches depend on.
    fp::CullConfig cullConfig() const {
        fp::CullConfig c;
        c.grid = grid_;
        c.layout = layout();
        c.samples = samples();
        c.slices = fp_.assign.slices;
        c.mostTested = mostTested();
        c.binned = binned();
        c.clustered = clustered();
        c.twoLists = r_.twoLists;
        c.blendedSpan = r_.blendPass;
        c.spheres = r_.spherePass;
        c.subgroupLanes = r_.subgroupCull ? ctx_.caps.subgroupSize : 0;
        return c;
    }

    void createDescriptors(FrameGraph& graph) {
        if (r_.spherePass) spheres_.prepare(graph);
        // fp_params is uploaded in prepare() and updateView(), outside the graph.
        culling_->prepare(graph, params_.buffer);
        if (binning_) {
            binning_->prepare(graph, params_.buffer, candidateWord_, offsetWord_, cap_.slots);
            // Clustered: each tile's slice rows, ceil(run / 32) words each, laid out by the
            // frame in the planned mask words (fp::layoutMasks's layout, on the GPU).
            if (clustered())
                binning_->publishWords(params_.buffer, fp_.assign.slices, 0, cap_.maskWords,
                                       maskOffsetWord_);
        }
    }

    GpuContext& ctx_;
    SceneGpu& scene_;
    SceneFeatures features_;
    fp::Settings fp_; // the settings, typed once (fp_settings.h); what follows is derived
    // The settings' values as the passes take them.
    uint32_t layout() const { return uint32_t(fp_.lists); } // TP_FP_LAYOUT_*
    bool binned() const { return fp_.assign.binned(); }
    bool clustered() const { return fp_.assign.clustered(); }
    uint32_t samples() const { return fp_.sampling.samples; }
    la::TileGrid grid_;
    la::LightClasses classes_;
    bool manyViews_ = false;         // RenderSettings::manyViews: the lists get headroom
    VkFormat hdrFormat_;             // hdr and hdr_msaa: --hdr, resolved (fp_.hdr)
    fp::Resolved r_;                 // which optional passes and variants run (fp_config.h)
    ResourceHandle masks_;
    std::vector<uint32_t> maskBits_; // read back: clustered statistics
    fp::ViewBins bins_;              // the current view's bound, offsets, candidates, mask rows
    fp::ViewCapacity cap_;           // what the plan's buffers hold (fp::planCapacity)
    std::unique_ptr<la::GpuBinning> binning_; // r_.gpuBinning: the light_binning pass
    uint64_t candidateWord_ = 0;              // the candidates' first word in fp_params
    uint64_t offsetWord_ = 0;                 // the tile offsets' first word in fp_params
    uint64_t maskOffsetWord_ = 0;             // clustered: the mask rows' offsets' first word
    fp::ListSizes lists_;

    ResourceHandle hdr_, depth_, hdrMsaa_, depthMsaa_, tiles_, indices_, counter_;
    Buffer params_;
    fp::LightSpheres spheres_{ctx_, scene_};
    std::optional<fp::LightCulling>
        culling_; // made once the lists are sized (its batches depend on them)
    std::optional<la::BlendedBounds>
        blendBounds_; // blended scenes: where each tile's blended fragments are
    std::optional<la::BlendedBounds>
        centreBounds_; // --msaa-shading pixel under MSAA: where the opaque fragments' centres are
    std::optional<passes::MeshletCull> cull_; // --cull-geometry frustum: meshlet_cull
    std::optional<passes::DepthPrepass> prepass_;
    std::optional<ShadowMaps> shadows_;         // the atlas (shadow_maps) with --shadows
    std::optional<fp::ForwardShading> shading_; // forward_opaque, forward_transparent

    std::vector<gpu::FpTileLists> tileLists_;
    std::vector<la::TileBlendedBounds> blended_; // read back: blended scenes' statistics
    uint32_t nodesUsed_ = 0;
    bool collected_ = false;
};

} // namespace

std::unique_ptr<Renderer> createForwardPlusRenderer(const RendererCreateInfo& info) {
    return std::make_unique<ForwardPlusRenderer>(info);
}

} // namespace tp
