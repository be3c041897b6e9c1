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
#include "core/image/difference.h"
#include "core/render/msaa_knob.h"
#include "core/render/scene_gpu.h"
#include "core/lightassign/bin_knob.h"
#include "core/lightassign/blended_bounds.h"
#include "core/lightassign/gpu_binning.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/light_classes.h"
#include "core/lightassign/loop_knob.h"
#include "core/lightassign/tile_grid.h"
#include "forwardplus/forwardplus_debug.h"
#include "forwardplus/forwardplus_shared.h"
#include "forwardplus/light_culling.h"
#include "forwardplus/list_counters.h"
#include "forwardplus/light_lists.h"
#include "forwardplus/light_spheres.h"

namespace tp {
namespace {

constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT; // storage-precision choice (docs)
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

uint32_t layoutFromName(const std::string& name) {
    if (name == "compact") return TP_FP_LAYOUT_COMPACT;
    if (name == "fixed") return TP_FP_LAYOUT_FIXED;
    if (name == "linked") return TP_FP_LAYOUT_LINKED;
    throw RendererError("unknown light-list layout '" + name + "' (compact, fixed, linked)");
}

class ForwardPlusRenderer final : public Renderer {
  public:
    explicit ForwardPlusRenderer(const RendererCreateInfo& info)
        : ctx_(info.ctx), scene_(info.scene), features_(info.features), settings_(info.settings) {
        layout_ = layoutFromName(settings_.text("light-lists"));
        binned_ = settings_.text("light-cull") == "binned";
        gpuBinning_ = binned_ && la::resolveLightBin(ctx_, settings_.text("light-bin")) == "gpu";
        clustered_ = settings_.text("light-assign") == "clustered";
        slices_ = settings_.integer("slices");
        // --light-spheres: the pass pays on a CPU device (lavapipe runs each candidate's
        // transform in every tile it is tested in); on a GPU the transform is cheap and the
        // buffer (16 MB at 1,000,000 lights) would take Forward+ past 100 MB there.
        const std::string spheres = settings_.text("light-spheres");
        spherePass_ = spheres == "pass" || (spheres == "auto" && ctx_.isCpuDevice());
        // --light-loop subgroup where the device has the operations; otherwise the lane loop
        // (the same image), with a note in the report.
        if (clustered_ && settings_.text("light-loop") == "subgroup") {
            subgroupMissing_ = la::subgroupLoopUnsupported(ctx_.caps);
            subgroupLoop_ = subgroupMissing_.empty();
        }
        // --cull-by: asked for, a subgroup per tile must be possible; auto takes it on a GPU that can.
        const std::string cullBy = settings_.text("cull-by");
        const std::string noSubgroupCull = fp::subgroupCullingUnsupported(ctx_.caps);
        if (cullBy == "subgroup" && !noSubgroupCull.empty())
            throw RendererError("--cull-by subgroup: " + noSubgroupCull + " (use --cull-by invocation)");
        subgroupCull_ = cullBy == "subgroup" || (cullBy == "auto" && !ctx_.isCpuDevice() && noSubgroupCull.empty());
        if (clustered_ && layout_ != TP_FP_LAYOUT_COMPACT)
            throw RendererError("--light-assign clustered needs --light-lists compact (got '" +
                                settings_.text("light-lists") + "')");
        grid_ = la::makeTileGrid(settings_.width, settings_.height, settings_.integer("tile"));
        // Two lists only when something is blended (and drawn); clustered has one list per
        // tile whose span covers the blended surfaces too.
        blendPass_ = features_.blended && scene_.hasDraws(DrawFilter::Blend);
        twoLists_ = blendPass_ && !clustered_;
        numLists_ = twoLists_ ? 2 : 1;
        classes_ = la::classifyLights(scene_.lightsGpu());
        if (layout_ != TP_FP_LAYOUT_FIXED || binned_) boundLists();
        lists_ = fp::sizeLists(ctx_, {layout_, settings_.text("light-lists"), grid_.count(),
                                      settings_.integer("tile-capacity"), boundSlots_, numLists_});
        culling_.emplace(ctx_, scene_, cullConfig());
        if (blendPass_) blendBounds_.emplace(ctx_, scene_);
    }

    ~ForwardPlusRenderer() override {
        VkDevice d = ctx_.device;
        for (VkPipeline p : {prepassOpaque_, prepassMask_, shade_[0], shade_[1], shade_[2]})
            if (p) vkDestroyPipeline(d, p, nullptr);
        if (shadeLayout_) vkDestroyPipelineLayout(d, shadeLayout_, nullptr);
        if (sceneLayout_) vkDestroyPipelineLayout(d, sceneLayout_, nullptr);
        destroyPassSet(ctx_, shadeSet_);
    }

    void plan(FrameGraph& graph) override {
        const bool msaa = settings_.msaa > 1;
        const auto samples = VkSampleCountFlagBits(settings_.msaa);
        hdr_ = graph.createImage("hdr", {kHdrFormat, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                         "linear radiance, resolved (RGBA16F)"});
        depth_ = graph.createImage("depth", {kDepthFormat, 0, 0, VK_SAMPLE_COUNT_1_BIT,
                                             msaa ? "depth (resolved: sample 0)" : "prepass depth"});
        if (msaa) {
            hdrMsaa_ = graph.createImage("hdr_msaa", {kHdrFormat, 0, 0, samples, "per-sample radiance (RGBA16F)"});
            depthMsaa_ = graph.createImage("depth_msaa", {kDepthFormat, 0, 0, samples, "per-sample prepass depth"});
        }
        const ResourceHandle depthSrc = msaa ? depthMsaa_ : depth_;
        const ResourceHandle color = msaa ? hdrMsaa_ : hdr_;

        tiles_ = graph.createBuffer("tile_lists", VkDeviceSize(grid_.count()) * sizeof(gpu::FpTileLists),
                                    "per tile: list counts, starts, drops, depth bounds");
        indices_ = graph.createBuffer("light_indices", lists_.bytes, lists_.purpose);
        if (layout_ == TP_FP_LAYOUT_LINKED)
            counter_ = graph.createBuffer("node_counter", 16, "linked lists: node allocation counter");
        if (clustered_)
            masks_ = graph.createBuffer("cluster_masks", std::max<uint64_t>(maskLayout_.words * 4, 16),
                                        "per tile and depth slice: a bitmask over the tile's list");

        std::vector<PassUse> prepassUses = {{depthSrc, Use::DepthAttachment}};
        if (msaa) prepassUses.push_back({depth_, Use::DepthResolve});
        graph.addPass("depth_prepass", prepassUses, [this](PassContext& pc) { recordPrepass(pc); });

        if (layout_ == TP_FP_LAYOUT_LINKED)
            graph.addPass("node_counter_reset", {{counter_, Use::TransferDst}}, [this](PassContext& pc) {
                vkCmdFillBuffer(pc.cmd, pc.buffer(counter_).buffer, 0, VK_WHOLE_SIZE, 0);
            });

        if (binning_) binning_->plan(graph); // the candidates the culling reads, every frame
        // Blended depth bounds: the blended shading pass's fragments, before the culling reads them.
        ResourceHandle blendBounds;
        if (blendPass_)
            blendBounds = blendBounds_->plan(graph, {grid_, depthSrc, settings_.msaa, shadesPerSample(settings_),
                                                     shadesPerPixelUnderMsaa(settings_)});
        const ResourceHandle spheres = spherePass_ ? spheres_.plan(graph) : ResourceHandle{};
        culling_->plan(graph, {depthSrc, tiles_, indices_, counter_, masks_, blendBounds, spheres});

        // Uses with a binding are also the pass's descriptor set (createDescriptors).

        std::vector<PassUse> opaqueUses = {{color, Use::ColorAttachment},
                                           {depthSrc, Use::DepthTest},
                                           {tiles_, Use::StorageRead, TP_FP_BINDING_TILES},
                                           {indices_, Use::StorageRead, TP_FP_BINDING_INDICES}};
        if (clustered_) opaqueUses.push_back({masks_, Use::StorageRead, TP_FP_BINDING_CLUSTER_MASKS});
        if (msaa && !blendPass_) opaqueUses.push_back({hdr_, Use::ColorResolve});
        graph.addPass("forward_opaque", opaqueUses, [this](PassContext& pc) { recordShading(pc, false); });

        if (blendPass_) {
            std::vector<PassUse> uses = {{color, Use::ColorAttachment},
                                         {depthSrc, Use::DepthTest},
                                         {tiles_, Use::StorageRead, TP_FP_BINDING_TILES},
                                         {indices_, Use::StorageRead, TP_FP_BINDING_INDICES}};
            if (clustered_) uses.push_back({masks_, Use::StorageRead, TP_FP_BINDING_CLUSTER_MASKS});
            if (msaa) uses.push_back({hdr_, Use::ColorResolve});
            graph.addPass("forward_transparent", uses, [this](PassContext& pc) { recordShading(pc, true); });
        }
        graph.exportResource("hdr", hdr_);
        graph.exportResource("depth", depth_);
        // Read back after the frame for the statistics, debug images and tests.
        graph.exportResource("fp_tile_lists", tiles_);
        graph.exportResource("fp_light_indices", indices_);
        if (layout_ == TP_FP_LAYOUT_LINKED) graph.exportResource("fp_node_counter", counter_);
        if (clustered_) graph.exportResource("fp_cluster_masks", masks_);
        if (blendPass_) graph.exportResource("blended_bounds", blendBounds);
    }

    void prepare(FrameGraph& graph) override {
        createParams();
        if (blendBounds_) blendBounds_->prepare(graph);
        createDescriptors(graph);
        createPipelines();
    }

    void collectStats(FrameGraph& graph) override {
        std::vector<uint8_t> bytes = readbackBuffer(ctx_, graph.buffer(tiles_));
        tileLists_.resize(grid_.count());
        std::memcpy(tileLists_.data(), bytes.data(), tileLists_.size() * sizeof(gpu::FpTileLists));
        if (layout_ == TP_FP_LAYOUT_LINKED) {
            std::vector<uint8_t> c = readbackBuffer(ctx_, graph.buffer(counter_));
            std::memcpy(&nodesUsed_, c.data(), sizeof(uint32_t));
        }
        if (blendBounds_)
            blended_ = la::unpackBlendedBounds(readbackBuffer(ctx_, graph.buffer(blendBounds_->buffer())), grid_.count());
        if (clustered_) {
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
            out.push_back({"lights_per_tile_transparent", fp::lightsPerTileHeatMap(grid_, tileLists_, 1), true});
        out.push_back({"tile_depth_bounds", fp::tileDepthBoundsImage(grid_, tileLists_, scene_.frame().invProj), true});
        return out;
    }

    RendererStats stats() const override {
        RendererStats s;
        auto add = [&](const std::string& name, double v) { s.counters.push_back({name, v}); };
        add("tile_size", settings_.integer("tile"));
        add("tiles", grid_.count());
        add("light_lists", double(numLists_));
        add("directional_lights_unculled", double(classes_.directional.size()));
        add("local_lights", double(classes_.local.size()));
        add("hdr_storage_bits_per_channel", 16.0);
        add("light_list_slots", double(lists_.slots));
        add("culling_dispatches", double(culling_->dispatches())); // batches of candidates (lavapipe's loop limit)
        add("light_spheres_pass", spherePass_ ? 1.0 : 0.0);       // --light-spheres, resolved
        add("culling_by_subgroup", subgroupCull_ ? 1.0 : 0.0);     // --cull-by, resolved
        if (binned_) add("binned_candidates", double(gpuBinning_ ? boundSlots_ : candidates_.size()));
        if (binned_) add("light_binning_on_gpu", gpuBinning_ ? 1.0 : 0.0); // --light-bin, resolved
        if (clustered_) {
            add("slices", double(slices_));
            add("cluster_mask_words", double(maskLayout_.words));
            add("light_loop_subgroup", subgroupLoop_ ? 1.0 : 0.0); // 0: lane loop (asked for, or the fallback)
        }
        if (collected_) {
            static const std::vector<uint32_t> none;
            fp::ListCounterInput in{tileLists_, blended_, binned_ ? tileBound_ : none, maskLayout_.offsets, maskBits_};
            in.localLights = classes_.local.size();
            in.slices = slices_;
            in.twoLists = twoLists_;
            in.clustered = clustered_;
            in.blendPass = blendPass_;
            in.linked = layout_ == TP_FP_LAYOUT_LINKED;
            in.nodesUsed = nodesUsed_;
            in.poolNodes = lists_.poolNodes;
            fp::addListCounters(s.counters, in);
        }
        if (!blendPass_)
            s.leftOut.push_back({"transparent light list, blended depth bounds, forward_transparent pass and their "
                                 "memory",
                                 "the scene has no blended materials"});
        else if (clustered_)
            s.leftOut.push_back({"the second (transparent) light list per tile",
                                 "clustered: one list spans the tile's opaque range widened to its blended "
                                 "fragments' depths, and blended surfaces look up their own depth slice"});
        if (binned_ && !gpuBinning_)
            s.leftOut.push_back({"light_binning pass (GPU binning)", "--light-bin " + settings_.text("light-bin") +
                                                                       " resolved to cpu: candidates built once per configuration"});
        if (!clustered_)
            s.leftOut.push_back({"depth slices and their bitmasks (cluster_masks)", "--light-assign tiled"});
        if (!spherePass_)
            s.leftOut.push_back({"light_spheres pass and its buffer (16 bytes per light)",
                                 "--light-spheres " + settings_.text("light-spheres") +
                                     ": the culling computes each candidate's sphere itself"});
        if (!subgroupMissing_.empty())
            s.leftOut.push_back({"the subgroup light loop (--light-loop subgroup): shading uses the lane loop, "
                                 "the same image",
                                 subgroupMissing_});
        if (settings_.msaa == 1)
            s.leftOut.push_back({"MSAA targets (hdr_msaa, depth_msaa) and their resolve", "MSAA is 1x"});
        if (!scene_.hasDraws(DrawFilter::Mask))
            s.leftOut.push_back({"alpha-masked prepass and shading pipelines", "the scene has no masked materials"});
        if (!features_.spotLights)
            s.leftOut.push_back({"spot-light shading code (TP_SPEC_HAS_SPOT = 0)", "the scene has no spot lights"});
        if (layout_ != TP_FP_LAYOUT_LINKED)
            s.leftOut.push_back({"node counter and its reset pass", "only the 'linked' layout allocates nodes"});
        s.leftOut.push_back({"fp32 colour storage",
                             "hdr and hdr_msaa are RGBA16F (storage-precision choice: half the bytes of "
                             "RGBA32F; each rounding below one ulp, <= 2^-10 relative; values saturate at 65504)"});
        return s;
    }

  private:
    // The conservative tile rectangle of every local light (CPU, once per configuration: the
    // lights and the camera are fixed for a run), counted per tile: the compact layout's
    // bound; with binned culling also each tile's candidates, in ascending light order.
    void boundLists() {
        // The uploaded (camera-relative) view and lights: what the culling shader tests.
        const gpu::FrameUniforms& f = scene_.shadingFrame();
        // --light-bin gpu: the frame builds the candidates; one plan-time run sizes them.
        if (gpuBinning_) binning_ = std::make_unique<la::GpuBinning>(ctx_, scene_, grid_, classes_.local, "forwardplus");
        la::LightBins bins = gpuBinning_ ? binning_->sizes()
                                         : la::binLights(grid_, f.view, f.proj, scene_.shadingLights(), classes_.local, binned_);
        tileBound_ = std::move(bins.bound);
        tileOffsets_ = std::move(bins.offsets);
        boundSlots_ = bins.slots;
        maxBound_ = bins.maxBound;
        // 32-bit offsets index data[] in fp_params: refuse what they cannot address.
        if (boundSlots_ > 0xffffffffull - classes_.local.size() - grid_.count() - 64)
            throw RendererError("the tile lists need " + std::to_string(boundSlots_) +
                                " slots, more than 32-bit offsets address; use a larger --tile, a lower --res or "
                                "fewer lights");
        candidates_ = std::move(bins.candidates);
        if (clustered_) maskLayout_ = fp::sizeMasks(ctx_, tileBound_, slices_);
    }

    void createParams() {
        fp::ParamsInput in{grid_, &classes_, layout_, binned_, gpuBinning_, &tileOffsets_, &candidates_, boundSlots_,
                           &maskLayout_.offsets, uint32_t(settings_.integer("tile-capacity")), lists_};
        fp::PackedParams packed = fp::packParams(ctx_, in);
        candidateWord_ = packed.candidateWord;
        params_ = createBufferWithData(ctx_, packed.bytes.data(), packed.bytes.size(), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                       {"forwardplus", "", "fp_params", packed.purpose});
    }

    // The culling pass's configuration: what its shader variant, batches and dispatches depend on.
    fp::CullConfig cullConfig() const {
        fp::CullConfig c;
        c.grid = grid_;
        c.lists = settings_.text("light-lists");
        c.layout = layout_;
        c.samples = settings_.msaa;
        c.slices = slices_;
        c.mostTested = binned_ ? maxBound_ : uint32_t(classes_.local.size());
        c.binned = binned_;
        c.clustered = clustered_;
        c.twoLists = twoLists_;
        c.blendedSpan = blendPass_;
        c.spheres = spherePass_;
        c.subgroupLanes = subgroupCull_ ? ctx_.caps.subgroupSize : 0;
        return c;
    }

    void createDescriptors(FrameGraph& graph) {
        if (spherePass_) spheres_.prepare(graph);
        // fp_params is uploaded once in prepare(), outside the graph.
        culling_->prepare(graph, params_.buffer);
        if (binning_) binning_->prepare(graph, params_.buffer, candidateWord_);
        // forward_transparent declares the same bound uses and shares this set.
        shadeSet_ = graph.createPassSet("forward_opaque", VK_NULL_HANDLE, {{TP_FP_BINDING_PARAMS, params_.buffer}});
    }

    void createPipelines() {
        const auto samples = VkSampleCountFlagBits(settings_.msaa);
        sceneLayout_ = scene_.createPipelineLayout();
        shadeLayout_ = scene_.createPipelineLayout(shadeSet_.layout);

        // Depth prepass: opaque without a fragment shader, masked with the alpha test.
        GraphicsPipelineDesc pre;
        pre.samples = samples;
        pre.layout = sceneLayout_;
        pre.specConstants = scene_.specConstants(AlphaMode::Opaque);
        if (scene_.hasDraws(DrawFilter::Opaque)) prepassOpaque_ = createGraphicsPipeline(ctx_, pre);
        if (scene_.hasDraws(DrawFilter::Mask)) {
            pre.fragmentShader = "prepass_mask_frag";
            pre.specConstants = scene_.specConstants(AlphaMode::Mask);
            prepassMask_ = createGraphicsPipeline(ctx_, pre);
        }

        for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend}) {
            if (!scene_.hasDraws(DrawFilter(mode))) continue;
            GraphicsPipelineDesc d;
            // --msaa-shading: pixel runs once per pixel at its centre (no `sample` inputs, no
            // sample shading; the EQUAL depth test against the per-sample prepass gives each
            // sample its coverage, masked materials included); sample shades every sample.
            d.fragmentShader = std::string(clustered_ ? "fp_shading_clustered" : "fp_shading") +
                               (subgroupLoop_ ? "_subgroup" : "") + (shadesPerPixelUnderMsaa(settings_) ? "_pixel_frag" : "_frag");
            d.colorFormats = {kHdrFormat};
            d.samples = samples;
            d.sampleShading = shadesPerSample(settings_);
            d.layout = shadeLayout_;
            d.passSet = &shadeSet_;
            d.depthWrite = false;
            d.depthCompare = mode == AlphaMode::Blend ? VK_COMPARE_OP_GREATER : VK_COMPARE_OP_EQUAL;
            d.blend = mode == AlphaMode::Blend ? BlendMode::Alpha : BlendMode::None;
            d.specConstants = scene_.specConstants(mode);
            d.specConstants.push_back({TP_FP_SPEC_TILE_SIZE, settings_.integer("tile")});
            d.specConstants.push_back({TP_FP_SPEC_TWO_LISTS, twoLists_ ? 1u : 0u});
            d.specConstants.push_back({TP_FP_SPEC_LAYOUT, layout_});
            if (clustered_) {
                d.specConstants.push_back({TP_FP_SPEC_SLICES, slices_});
                d.specConstants.push_back({TP_FP_SPEC_BLENDED_SPAN, blendPass_ ? 1u : 0u});
            }
            shade_[uint32_t(mode)] = createGraphicsPipeline(ctx_, d);
        }
    }

    void recordPrepass(PassContext& pc) {
        const bool msaa = settings_.msaa > 1;
        DepthTarget depth{msaa ? depthMsaa_ : depth_, msaa ? depth_ : ResourceHandle{}};
        beginRendering(pc, {}, depth);
        scene_.bindSceneSet(pc.cmd, sceneLayout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
        scene_.recordDraws(pc.cmd, sceneLayout_, DrawFilter::Opaque, prepassOpaque_);
        scene_.recordDraws(pc.cmd, sceneLayout_, DrawFilter::Mask, prepassMask_);
        endRendering(pc);
    }

    void recordShading(PassContext& pc, bool transparent) {
        const bool msaa = settings_.msaa > 1;
        ColorTarget color;
        color.image = msaa ? hdrMsaa_ : hdr_;
        const bool lastPass = transparent || !blendPass_;
        if (msaa && lastPass) color.resolve = hdr_;
        color.clear = !transparent;
        DepthTarget depth{msaa ? depthMsaa_ : depth_, {}, false, true};
        beginRendering(pc, {color}, depth);
        scene_.bindSceneSet(pc.cmd, shadeLayout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
        vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, shadeLayout_, TP_SET_PASS, 1, &shadeSet_.set, 0,
                                nullptr);
        std::vector<AlphaMode> modes = transparent ? std::vector<AlphaMode>{AlphaMode::Blend}
                                                   : std::vector<AlphaMode>{AlphaMode::Opaque, AlphaMode::Mask};
        for (AlphaMode mode : modes)
            scene_.recordDraws(pc.cmd, shadeLayout_, DrawFilter(mode), shade_[uint32_t(mode)]);
        endRendering(pc);
    }

    GpuContext& ctx_;
    SceneGpu& scene_;
    SceneFeatures features_;
    RenderSettings settings_;
    uint32_t layout_ = TP_FP_LAYOUT_COMPACT;
    la::TileGrid grid_;
    bool twoLists_ = false;
    uint32_t numLists_ = 1;
    la::LightClasses classes_;
    bool binned_ = true, clustered_ = false, blendPass_ = false;
    uint32_t slices_ = 16;
    bool spherePass_ = false;      // --light-spheres resolved: the light_spheres pass runs
    bool subgroupCull_ = false;    // --cull-by resolved: one subgroup culls a tile
    bool subgroupLoop_ = false;    // clustered, --light-loop subgroup, and the device runs it
    std::string subgroupMissing_; // --light-loop subgroup asked for but unsupported: why
    fp::MaskLayout maskLayout_; // clustered: the slice rows' word offsets per tile
    ResourceHandle masks_;
    std::vector<uint32_t> maskBits_; // read back: clustered statistics
    std::vector<uint32_t> tileBound_, tileOffsets_, candidates_;
    uint64_t boundSlots_ = 0;
    uint32_t maxBound_ = 0; // binned: the most candidates of any tile (the culling batches' range)
    bool gpuBinning_ = false;                // --light-bin resolved to gpu (binned only)
    std::unique_ptr<la::GpuBinning> binning_; // then: the light_binning pass
    uint64_t candidateWord_ = 0;              // the candidates' first word in fp_params
    fp::ListSizes lists_;

    ResourceHandle hdr_, depth_, hdrMsaa_, depthMsaa_, tiles_, indices_, counter_;
    Buffer params_;
    fp::LightSpheres spheres_{ctx_, scene_};
    std::optional<fp::LightCulling> culling_; // made once the lists are sized (its batches depend on them)
    std::optional<la::BlendedBounds> blendBounds_; // blended scenes: where each tile's blended fragments are
    PassSet shadeSet_;
    VkPipelineLayout sceneLayout_ = VK_NULL_HANDLE, shadeLayout_ = VK_NULL_HANDLE;
    VkPipeline prepassOpaque_ = VK_NULL_HANDLE, prepassMask_ = VK_NULL_HANDLE;
    VkPipeline shade_[3] = {};

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
