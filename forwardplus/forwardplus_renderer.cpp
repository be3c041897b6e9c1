#include "forwardplus/forwardplus_renderer.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <optional>
#include <string>

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
#include "core/passes/shadow_maps.h"
#include "core/renderer/msaa_knob.h"
#include "forwardplus/forward_shading.h"
#include "forwardplus/forwardplus_debug.h"
#include "forwardplus/forwardplus_shared.h"
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
          fp_(fp::readSettings(info.settings)), manyViews_(info.settings.manyViews),
          hdrFormat_(fp_.hdr == HdrStorage::Fp16 ? VK_FORMAT_R16G16B16A16_SFLOAT
                                                 : VK_FORMAT_R32G32B32A32_SFLOAT) {
        gpuBinning_ = binned() && la::binsOnGpu(ctx_, fp_.assign.bin);
        // --light-spheres: the pass pays on a CPU device (lavapipe runs each candidate's
        // transform in every tile it is tested in); on a GPU the transform is cheap and the
        // buffer (16 MB at 1,000,000 lights) would take Forward+ past 100 MB there.
        spherePass_ = fp_.spheres == fp::Spheres::Pass ||
                      (fp_.spheres == fp::Spheres::Auto && ctx_.isCpuDevice());
        // --light-loop subgroup where the device has the operations; otherwise the lane loop
        // (the same image), with a note in the report.
        if (clustered() && fp_.loop == la::Loop::Subgroup) {
            subgroupMissing_ = la::subgroupLoopUnsupported(ctx_.caps);
            subgroupLoop_ = subgroupMissing_.empty();
        }
        // --cull-by: asked for, a subgroup per tile must be possible; auto takes it on a GPU that
        // can.
        const fp::CullBy cullBy = fp_.cullBy;
        const std::string noSubgroupCull = fp::subgroupCullingUnsupported(ctx_.caps);
        if (cullBy == fp::CullBy::Subgroup && !noSubgroupCull.empty())
            throw RendererError("--cull-by subgroup: " + noSubgroupCull +
                                " (use --cull-by invocation)");
        subgroupCull_ =
            cullBy == fp::CullBy::Subgroup ||
            (cullBy == fp::CullBy::Auto && !ctx_.isCpuDevice() && noSubgroupCull.empty());
        if (clustered() && layout() != TP_FP_LAYOUT_COMPACT)
            throw RendererError("--light-assign clustered needs --light-lists compact (got '" +
                                fp::listsText(fp_.lists) + "')");
        grid_ = la::makeTileGrid(fp_.width, fp_.height, fp_.assign.tile);
        // Two lists only when something is blended (and drawn); clustered has one list per
        // tile whose span covers the blended surfaces too.
        blendPass_ = features_.blended && scene_.hasDraws(DrawFilter::Blend);
        twoLists_ = blendPass_ && !clustered();
        numLists_ = twoLists_ ? 2 : 1;
        classes_ = la::classifyLights(scene_.lightsGpu());
        if (boundsLists()) boundLists();
        lists_ = fp::sizeLists(ctx_, {layout(), fp::listsText(fp_.lists), grid_.count(),
                                      fp_.tileCapacity, cap_.slots, numLists_});
        culling_.emplace(ctx_, scene_, cullConfig());
        if (blendPass_) blendBounds_.emplace(ctx_, scene_);
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

        prepass_.emplace(ctx_, scene_,
                         passes::DepthPrepassParams{samples(), scene_.drawList(DrawFilter::Opaque),
                                                    scene_.drawList(DrawFilter::Mask)});
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
        if (blendPass_)
            blendBounds =
                blendBounds_->plan(graph, {grid_, depthSrc, samples(), fp_.sampling.perSample(),
                                           fp_.sampling.perPixelUnderMsaa()});
        ResourceHandle centreBounds;
        if (centreBounds_) {
            la::BlendedBoundsConfig centres{grid_, depthSrc, samples(), false, true};
            centres.opaque = true;
            centreBounds = centreBounds_->plan(graph, centres);
        }
        const ResourceHandle spheres = spherePass_ ? spheres_.plan(graph) : ResourceHandle{};
        culling_->plan(graph, {depthSrc, tiles_, indices_, counter_, masks_, blendBounds, spheres,
                               centreBounds});

        shadows_.emplace(ctx_, scene_, ShadowMaps::Residency::Atlas); // shadow_maps, if any
        shadows_->plan(graph);
        shading_.emplace(ctx_, scene_,
                         fp::ShadingConfig{fp_.sampling, fp_.assign.tile, layout(),
                                           fp_.assign.slices, twoLists_, clustered(), blendPass_,
                                           subgroupLoop_});
        shading_->plan(graph, {hdr_, hdrMsaa_, depth_, depthMsaa_, tiles_, indices_, masks_,
                               hdrFormat_, &*shadows_});
        graph.exportResource("hdr", hdr_);
        graph.exportResource("depth", depth_);
        // Read back after the frame for the statistics, debug images and tests.
        graph.exportResource("fp_tile_lists", tiles_);
        graph.exportResource("fp_light_indices", indices_);
        if (layout() == TP_FP_LAYOUT_LINKED) graph.exportResource("fp_node_counter", counter_);
        if (clustered()) graph.exportResource("fp_cluster_masks", masks_);
        if (blendPass_) graph.exportResource("blended_bounds", blendBounds);
    }

    void prepare(FrameGraph& graph) override {
        createParams();
        prepass_->prepare();
        if (blendBounds_) blendBounds_->prepare(graph);
        if (centreBounds_) centreBounds_->prepare(graph);
        createDescriptors(graph);
        shadows_->prepare(graph);
        shading_->prepare(graph, params_.buffer);
    }

    // A new view (the camera or the lights' positions): its bins on the CPU (or the GPU
    // binning's sizing run) laid out in the planned lists, fp_params and the shading's lights
    // copy uploaded again; the frame's passes (spheres, binning, culling) recompute the rest.
    // false when the view outgrew the lists' room or the light types changed.
    bool updateView(FrameGraph&) override {
        if (shadows_->stale()) return false; // other shadowed lights or map sizes
        const la::LightClasses classes = la::classifyLights(scene_.lightsGpu());
        if (classes.directional != classes_.directional || classes.local != classes_.local)
            return false; // fp_params' light classes and the shading's loop are planned
        if (boundsLists()) {
            fp::ViewBins bins = fp::binView(scene_, viewBinning());
            if (!cap_.holds(bins) || (binning_ && !binning_->bigListFits())) return false;
            bins_ = std::move(bins);
        }
        const fp::PackedParams packed = packParams();
        if (packed.bytes.size() != params_.size) return false; // not laid out as planned
        uploadBufferData(ctx_, params_, packed.bytes.data(), packed.bytes.size());
        culling_->setMostTested(mostTested());
        shading_->updateLights();
        return true;
    }

    void collectStats(FrameGraph& graph) override {
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
        collected_ = true;
    }

    std::vector<DebugImage> debugImages(FrameGraph&) override {
        if (!collected_) return {};
        std::vector<DebugImage> out;
        out.push_back({"lights_per_tile", fp::lightsPerTileHeatMap(grid_, tileLists_, 0), true});
        if (twoLists_)
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
        add("light_lists", double(numLists_));
        add("directional_lights_unculled", double(classes_.directional.size()));
        add("local_lights", double(classes_.local.size()));
        add("hdr_storage_bits_per_channel",
            fp_.hdr == HdrStorage::Fp16 ? 16.0 : 32.0); // --hdr, resolved
        add("light_list_slots", double(lists_.slots));
        add("culling_dispatches",
            double(culling_->dispatches())); // batches of candidates (lavapipe's loop limit)
        add("light_spheres_pass", spherePass_ ? 1.0 : 0.0);    // --light-spheres, resolved
        add("culling_by_subgroup", subgroupCull_ ? 1.0 : 0.0); // --cull-by, resolved
        if (binned())
            add("binned_candidates", double(gpuBinning_ ? bins_.slots : bins_.candidates.size()));
        if (binned()) add("light_binning_on_gpu", gpuBinning_ ? 1.0 : 0.0); // --light-bin, resolved
        if (clustered()) {
            add("slices", double(fp_.assign.slices));
            add("cluster_mask_words", double(bins_.masks.words));
            add("light_loop_subgroup",
                subgroupLoop_ ? 1.0 : 0.0); // 0: lane loop (asked for, or the fallback)
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
            in.twoLists = twoLists_;
            in.clustered = clustered();
            in.blendPass = blendPass_;
            in.linked = layout() == TP_FP_LAYOUT_LINKED;
            in.nodesUsed = nodesUsed_;
            in.poolNodes = lists_.poolNodes;
            fp::addListCounters(s.counters, in);
            addLightWork(s);
        }
        addLeftOut(s);
        return s;
    }

  private:
    // Every shaded fragment evaluates its tile's (cluster's) list and the unculled directional
    // lights: the lists' mean stands for the fragment's list.
    void addLightWork(RendererStats& s) const {
        const double directional = double(classes_.directional.size());
        // Fragments lie in the tiles with geometry: the list's mean over those (sky tiles' lists
        // are empty). Clustered: the mean over every cluster, an under-estimate.
        const char* opaque = clustered() ? "lights_per_cluster_mean" : "lights_per_tile_mean";
        const double tiles = s.counter("tiles"), withGeometry = tiles - s.counter("tiles_without_geometry");
        const double opaqueShare = clustered() ? 1.0 : tiles / std::max(1.0, withGeometry);
        s.lightWork.push_back({"forward_opaque", PassLightWork::Base::Fragments,
                               s.counter(opaque) * opaqueShare + directional, false,
                               std::string(opaque) + (clustered() ? "" : " over the tiles with geometry") +
                                   " + directional lights, per fragment"});
        if (!blendPass_) return;
        // Blended fragments lie in the tiles with blended fragments: the list's mean over those.
        const char* blended = clustered() ? "lights_per_front_cluster_mean" : "transparent_lights_per_tile_mean";
        const double share = clustered() ? 1.0 : s.counter("tiles") / std::max(1.0, s.counter("tiles_with_blended_fragments"));
        s.lightWork.push_back({"forward_transparent", PassLightWork::Base::Fragments,
                               s.counter(blended, s.counter(opaque)) * share + directional, false,
                               std::string(blended) + (clustered() ? "" : " over the tiles with blended fragments") +
                                   " + directional lights, per fragment"});
    }

    // What this configuration leaves out, and why (the report's "left out" list).
    void addLeftOut(RendererStats& s) const {
        if (!blendPass_)
            s.leftOut.push_back(
                {"transparent light list, blended depth bounds, forward_transparent pass and their "
                 "memory",
                 "the scene has no blended materials"});
        else if (clustered())
            s.leftOut.push_back(
                {"the second (transparent) light list per tile",
                 "clustered: one list spans the tile's opaque range widened to its blended "
                 "fragments' depths, and blended surfaces look up their own depth slice"});
        if (binned() && !gpuBinning_)
            s.leftOut.push_back({"light_binning pass (GPU binning)",
                                 "--light-bin " + la::lightBinKnob().text(fp_.assign.bin) +
                                     " resolved to cpu: candidates built on the CPU per view"});
        if (!clustered())
            s.leftOut.push_back(
                {"depth slices and their bitmasks (cluster_masks)", "--light-assign tiled"});
        if (!spherePass_)
            s.leftOut.push_back({"light_spheres pass and its buffer (16 bytes per light)",
                                 "--light-spheres " + fp::spheresText(fp_.spheres) +
                                     ": the culling computes each candidate's sphere itself"});
        if (!subgroupMissing_.empty())
            s.leftOut.push_back(
                {"the subgroup light loop (--light-loop subgroup): shading uses the lane loop, "
                 "the same image",
                 subgroupMissing_});
        if (samples() == 1)
            s.leftOut.push_back(
                {"MSAA targets (hdr_msaa, depth_msaa) and their resolve", "MSAA is 1x"});
        if (!scene_.hasDraws(DrawFilter::Mask))
            s.leftOut.push_back({"alpha-masked prepass and shading pipelines",
                                 "the scene has no masked materials"});
        if (!features_.spotLights)
            s.leftOut.push_back(
                {"spot-light shading code (TP_SPEC_HAS_SPOT = 0)", "the scene has no spot lights"});
        if (layout() != TP_FP_LAYOUT_LINKED)
            s.leftOut.push_back(
                {"node counter and its reset pass", "only the 'linked' layout allocates nodes"});
        if (fp_.hdr == HdrStorage::Fp16)
            s.leftOut.push_back(
                {"fp32 colour storage",
                 "--hdr " + std::string(hdrText(fp_.hdr)) +
                     ": hdr and hdr_msaa are RGBA16F (half the bytes of RGBA32F; each rounding "
                     "below one ulp, <= 2^-10 relative; values saturate at 65504)"});
    }

    // Whether the lists' layout follows the view: the compact and linked layouts' bound, binned
    // culling's candidates (fixed, unbinned: nothing to bin).
    bool boundsLists() const { return layout() != TP_FP_LAYOUT_FIXED || binned(); }

    fp::ViewBinning viewBinning() {
        return {grid_, &classes_, binned(), clustered(), fp_.assign.slices, binning_.get()};
    }

    // The conservative tile rectangle of every local light (CPU, per view: updateView bins
    // again), counted per tile: the compact layout's bound; with binned culling also each
    // tile's candidates, in ascending light order. The plan's room: cap_.
    void boundLists() {
        // --light-bin gpu: the frame builds the candidates; a sizing run per view sizes them.
        if (gpuBinning_)
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
                                {ctx_.caps.maxStorageBufferRange, numLists_,
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
        params_ = createBufferWithData(ctx_, packed.bytes.data(), packed.bytes.size(),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       {"forwardplus", "", "fp_params", packed.purpose});
    }

    // The most lights a tile tests: the culling's batches.
    uint32_t mostTested() const {
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
        c.twoLists = twoLists_;
        c.blendedSpan = blendPass_;
        c.spheres = spherePass_;
        c.subgroupLanes = subgroupCull_ ? ctx_.caps.subgroupSize : 0;
        return c;
    }

    void createDescriptors(FrameGraph& graph) {
        if (spherePass_) spheres_.prepare(graph);
        // fp_params is uploaded in prepare() and updateView(), outside the graph.
        culling_->prepare(graph, params_.buffer);
        if (binning_) binning_->prepare(graph, params_.buffer, candidateWord_);
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
    bool twoLists_ = false;
    uint32_t numLists_ = 1;
    la::LightClasses classes_;
    bool blendPass_ = false;
    bool spherePass_ = false;     // --light-spheres resolved: the light_spheres pass runs
    bool subgroupCull_ = false;   // --cull-by resolved: one subgroup culls a tile
    bool subgroupLoop_ = false;   // clustered, --light-loop subgroup, and the device runs it
    std::string subgroupMissing_; // --light-loop subgroup asked for but unsupported: why
    bool manyViews_ = false;         // RenderSettings::manyViews: the lists get headroom
    VkFormat hdrFormat_;             // hdr and hdr_msaa: --hdr, resolved (fp_.hdr)
    ResourceHandle masks_;
    std::vector<uint32_t> maskBits_; // read back: clustered statistics
    fp::ViewBins bins_;              // the current view's bound, offsets, candidates, mask rows
    fp::ViewCapacity cap_;           // what the plan's buffers hold (fp::planCapacity)
    bool gpuBinning_ = false;                 // --light-bin resolved to gpu (binned only)
    std::unique_ptr<la::GpuBinning> binning_; // then: the light_binning pass
    uint64_t candidateWord_ = 0;              // the candidates' first word in fp_params
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
