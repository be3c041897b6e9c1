#include "core/passes/tiled_lighting.h"

#include <algorithm>
#include <cstring>
#include <initializer_list>
#include <utility>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/readback.h"
#include "core/gpu/resources.h"
#include "core/gpu/stand_ins.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/lightassign/light_bins.h"
#include "core/lightassign/light_classes.h"
#include "core/passes/shadow_maps.h"
#include "core/renderer/renderer.h"

namespace tp {

TiledLighting::~TiledLighting() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    if (sampler_) vkDestroySampler(ctx_.device, sampler_, nullptr);
    destroyPassSet(ctx_, set_);
}

void TiledLighting::plan(FrameGraph& graph, const SurfaceSource& source,
                         const TiledLightingTargets& t, bool listsOnly,
                         ResourceHandle transparentMasks, ResourceHandle blendBounds) {
    source_ = source;
    t_ = t;
    listsOnly_ = listsOnly;
    transparentMasks_ = transparentMasks;
    if (binned_) bound(t.grid, graph.owner());
    if (binning_) binning_->plan(graph); // the frame's light_binning runs before this pass
    // The lights as a uniform buffer, read by every light loop of the pass (and of the blended
    // forward pass, which binds this one: lightsUbo()) on a CPU device
    // (core/passes/lights_ubo.h): light k at slot k.
    lightsUbo_.emplace(ctx_, scene_, graph.owner(), "lights_ubo");
    // The tiles' depth bounds, reduced by a pass of their own before this one.
    depthBounds_ = std::make_unique<TileDepthBounds>(ctx_, scene_);
    const ResourceHandle tileDepth = depthBounds_->plan(graph, source.depth, source.samples, t.grid);
    // Each resource once, with the binding (set TP_SET_PASS) the shader reads it at.
    std::vector<PassUse> uses;
    if (!listsOnly) uses = source.attributes;
    uses.push_back({source.depth, Use::Sampled, TP_TL_BINDING_DEPTH});
    if (!listsOnly)
        uses.push_back(
            {t.hdrMsaa.valid() ? t.hdrMsaa : t.hdr, Use::StorageWrite, TP_TL_BINDING_HDR});
    uses.push_back({tileDepth, Use::StorageRead, TP_TL_BINDING_TILE_DEPTH});
    uses.push_back({t.tileStats, Use::StorageWrite, TP_TL_BINDING_TILE_STATS});
    if (t.transparentLists.valid())
        uses.push_back({t.transparentLists, Use::StorageWrite, TP_TL_BINDING_TRANSPARENT_LISTS});
    if (transparentMasks.valid())
        uses.push_back({transparentMasks, Use::StorageWrite, TP_TL_BINDING_TRANSPARENT_MASKS});
    if (t.transparentLists.valid())
        uses.push_back({blendBounds, Use::StorageRead, TP_TL_BINDING_BLEND_BOUNDS});
    if (t.debug.valid()) uses.push_back({t.debug, Use::StorageWrite, TP_TL_BINDING_DEBUG});
    if (shadowed()) // set 2, not the pass's set
        for (const PassUse& u : t.shadows->sampledUses()) uses.push_back(u);
    graph.addPass(passName(), uses, [this](PassContext& pc) { record(pc); });
}

bool TiledLighting::shadowed() const {
    return !listsOnly_ && t_.shadows && t_.shadows->enabled();
}

std::string TiledLighting::passName() const {
    return listsOnly_ ? "transparent_light_lists" : "tiled_lighting";
}

namespace {
// A variant key of passes/tiled_lighting.h (TP_TL_VARIANT_KEY, TP_TL_LISTS_KEY) with each
// {field} replaced by its value: the names CMake compiled from the same key.
std::string fillKey(std::string key, std::initializer_list<std::pair<const char*, std::string>> fields) {
    for (const auto& [field, value] : fields) {
        const std::string token = std::string("{") + field + "}";
        for (size_t at = key.find(token); at != std::string::npos; at = key.find(token))
            key.replace(at, token.size(), value);
    }
    return key;
}
} // namespace

std::string TiledLighting::shaderName() const {
    const std::string& family = source_.shaderFamily;
    if (listsOnly_) return family + fillKey(TP_TL_LISTS_KEY, {{"m", msaa() ? "1" : "0"}}) + "_comp";
    const int m = !msaa() ? 0 : t_.hdrMsaa.valid() ? 2 : 1;
    return family +
           fillKey(TP_TL_VARIANT_KEY,
                   {{"m", std::to_string(m)},
                    {"e", source_.emissive ? "1" : "0"},
                    {"t", t_.transparentLists.valid() ? "1" : "0"},
                    {"d", t_.debug.valid() ? "1" : "0"},
                    {"h", t_.hdrFormat == VK_FORMAT_R16G16B16A16_SFLOAT ? "_h16" : ""}}) +
           "_comp";
}

void TiledLighting::prepare(FrameGraph& graph) {
    depthBounds_->prepare(graph);
    // texelFetch only: the sampler's filtering is never used.
    sampler_ = createNearestClampSampler(ctx_);
    std::vector<ExternalBuffer> externals;
    if (t_.transparentLists.valid()) {
        // Uploaded once per configuration: the compact layout's runs (blended_lists.h plans them).
        // Transfer source: GPU binning reads the frame's layout back for statistics (collect).
        listOffsets_ = createBufferWithData(
            ctx_, t_.listOffsets.data(), t_.listOffsets.size() * 4,
            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
            {graph.owner(), "", "transparent_list_offsets",
             "per tile: first slot of its transparent list (prefix sum)"});
        externals.push_back({TP_TL_BINDING_LIST_OFFSETS, listOffsets_.buffer});
        if (!transparentMasks_.valid()) {
            // The shader declares the slice rows whenever it writes lists; only clustered uses
            // them.
            noMasks_ =
                createStandInBuffer(ctx_, {graph.owner(), "", "transparent_cluster_masks_unused",
                                           "stand-in: slice rows are clustered only"});
            externals.push_back({TP_TL_BINDING_TRANSPARENT_MASKS, noMasks_.buffer});
        }
    }
    uploadCandidates(graph);
    externals.push_back({TP_TL_BINDING_CANDIDATES, candidates_.buffer});
    externals.push_back(
        {TP_TL_BINDING_LIGHTS_UBO, lightsUbo_->buffer(), VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER});
    if (!listsOnly_)
        externals.insert(externals.end(), source_.buffers.begin(), source_.buffers.end());
    set_ = graph.createPassSet(passName(), sampler_, externals);

    layout_ = scene_.createPipelineLayout(set_.layout,
                                          shadowed() ? t_.shadows->setLayout() : VK_NULL_HANDLE);
    std::vector<SpecConstant> spec = scene_.specConstants(AlphaMode::Opaque);
    spec.push_back({TP_SPEC_TILE_SIZE, t_.grid.tileSize});
    spec.insert(spec.end(), source_.constants.begin(), source_.constants.end());
    spec.push_back({TP_SPEC_SAMPLES, source_.samples});
    spec.push_back({TP_TL_SPEC_EVERY_SAMPLE, source_.everySample ? 1u : 0u});
    spec.push_back({TP_TL_SPEC_BINNED, binned_ ? 1u : 0u});
    spec.push_back({TP_TL_SPEC_LIGHTS_UBO, lightsUbo_->active() ? 1u : 0u});
    // The workgroup (--tile-group; tiled_lighting.h): a GPU's latency wants a tile's pixels one
    // an invocation.
    const uint32_t group = la::tileGroupEdge(ctx_, group_, t_.grid.tileSize);
    spec.push_back({TP_TL_SPEC_GROUP_X, group});
    spec.push_back({TP_TL_SPEC_GROUP_Y, group});
    spec.push_back({TP_TL_SPEC_SLICES, listsOnly_ ? 0u : slices_}); // lists only: no shading
    // The shared slice masks: clustered shading only (tiled groups keep one word).
    spec.push_back(
        {TP_TL_SPEC_MASK_WORDS, !listsOnly_ && slices_ > 0 ? TP_TL_CLUSTER_MASK_WORDS : 1u});
    std::string shader = shaderName();
    if (shadowed()) t_.shadows->apply(shader, spec); // the _shadow twin
    pipeline_ = createComputePipeline(ctx_, shader, spec, layout_, &set_);
}

uint64_t viewCapacity(uint64_t need, uint64_t floor, uint64_t most, bool manyViews) {
    if (!manyViews) return need;
    return std::max(need, std::min(std::max(need * kViewHeadroom, floor), most));
}

const std::vector<uint32_t>& TiledLighting::bound(const la::TileGrid& grid,
                                                  const std::string& owner) {
    if (!binnedOnce_) {
        binnedOnce_ = true;
        if (gpuBinning_) { // sized now (one plan-time run); the frame's pass fills the runs
            const std::vector<uint32_t> local = la::classifyLights(scene_.shadingLights()).local;
            binning_ =
                std::make_unique<la::GpuBinning>(ctx_, scene_, grid, local, owner, manyViews_);
        }
        t_.grid = grid; // plan() sets it again
        bin();
    }
    return bins_.bound;
}

void TiledLighting::bin() {
    if (binning_) {
        bins_ = binning_->sizes();
        return;
    }
    const gpu::FrameUniforms& f = scene_.shadingFrame();
    const std::vector<gpu::LightGpu>& lights = scene_.shadingLights();
    bins_ = la::binLights(t_.grid, f.view, f.proj, lights, la::classifyLights(lights).local, true);
}

std::vector<uint32_t> TiledLighting::candidateWords(const la::LightClasses& classes) {
    const uint32_t tiles = t_.grid.count();
    const uint32_t directional = uint32_t(classes.directional.size());
    std::vector<uint32_t> words(TP_TL_CAND_HEADER, 0);
    words[TP_TL_CAND_DIRECTIONAL] = directional;
    words[TP_TL_CAND_OFFSETS] = TP_TL_CAND_HEADER + directional;
    words[TP_TL_CAND_RUNS] = TP_TL_CAND_HEADER + directional + tiles + 1;
    words.insert(words.end(), classes.directional.begin(), classes.directional.end());
    words.insert(words.end(), bins_.offsets.begin(), bins_.offsets.end());
    words.insert(words.end(), bins_.candidates.begin(), bins_.candidates.end());
    // GPU binning: the longest run the frame is recorded for (a longer one is an overflow).
    maxCandidates_ = directional + (binning_ ? binning_->runBound() : bins_.maxBound);
    candidateCount_ = uint64_t(directional) * tiles + bins_.slots;
    std::vector<uint32_t>().swap(bins_.candidates); // uploaded: the host copy is not needed again
    return words;
}

// Binned: per tile, the point/spot lights whose conservative tile rectangle covers it (CPU,
// binned for the view planned, again by updateView for each new one), after the directional
// lights, which every tile takes. Otherwise a header saying "no candidates". The runs get
// headroom for later views under manyViews (viewCapacity).
void TiledLighting::uploadCandidates(FrameGraph& graph) {
    std::vector<uint32_t> words(TP_TL_CAND_HEADER, 0);
    const uint32_t tiles = t_.grid.count();
    if (binned_) {
        la::LightClasses classes = la::classifyLights(scene_.shadingLights());
        const uint64_t fixed =
            uint64_t(TP_TL_CAND_HEADER) + classes.directional.size() + tiles + 1;
        // The buffer's size from the unclamped slot count: refused before it is built.
        const uint64_t bytes = (fixed + bins_.slots) * 4;
        if (bytes > ctx_.caps.maxStorageBufferRange)
            throw RendererError(
                graph.owner() + ": the binned light candidates need " + std::to_string(bytes) +
                " bytes, more than maxStorageBufferRange (" +
                std::to_string(ctx_.caps.maxStorageBufferRange) + ") of " + ctx_.info.name +
                "; use a larger --tile, a lower --res, fewer lights or --light-cull all");
        // A view's slots are at most every local light in every tile.
        slotCapacity_ =
            viewCapacity(bins_.slots, kViewHeadroom * tiles,
                         std::min(uint64_t(classes.local.size()) * tiles,
                                  ctx_.caps.maxStorageBufferRange / 4 - fixed),
                         manyViews_);
        directional_ = classes.directional;
        words = candidateWords(classes);
        words.resize(fixed + slotCapacity_, 0); // GPU binning: light_binning writes the runs
    } else {
        candidateCount_ = uint64_t(scene_.lightCount()) * tiles;
    }
    candidates_ = createBufferWithData(
        ctx_, words.data(), words.size() * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
        {graph.owner(), "", "light_candidates",
         binned_ ? "binned culling: directional lights, per-tile offsets, candidates" +
                       std::string(slotCapacity_ > bins_.slots ? " (headroom for other views)" : "")
                 : "binned culling off (--light-cull all): header only"});
    if (binning_)
        binning_->prepare(graph, candidates_.buffer, words[TP_TL_CAND_RUNS],
                          words[TP_TL_CAND_OFFSETS], slotCapacity_);
}

bool TiledLighting::updateView(FrameGraph&) {
    if (lightsUbo_) lightsUbo_->update(); // the lights' positions follow the view
    if (!binned_) return true; // every tile tests every light: nothing else depends on the view
    la::LightClasses classes = la::classifyLights(scene_.shadingLights());
    if (classes.directional != directional_) return false; // the header's layout would move
    if (binning_) {
        // The frame bins the view and writes the offsets and runs (light_binning.h); a view
        // past the room is caught after its frames (overflowed): nothing read back here.
        binning_->followView();
        return true;
    }
    bin();
    if (bins_.slots > slotCapacity_) return false;
    std::vector<uint32_t> words = candidateWords(classes);
    uploadBufferData(ctx_, candidates_, words.data(), words.size() * 4);
    return true;
}

void TiledLighting::publishListWords(uint64_t room, bool masks) {
    if (binning_)
        binning_->publishWords(listOffsets_.buffer, 1, uint32_t(directional_.size()), room, 0,
                               !masks);
}

bool TiledLighting::overflowed(FrameGraph& graph) {
    return binning_ && binning_->overflowed(graph, lightBatch(), uint32_t(directional_.size()));
}

// Lights per dispatch of the shading loop (record's batches).
uint32_t TiledLighting::lightBatch() const {
    const uint32_t lights = binned_ ? maxCandidates_ : scene_.lightCount();
    // Lists only: no shading loop, one dispatch whatever the light count.
    uint32_t batch = listsOnly_
                         ? std::max(lights, 1u)
                         : tiledLightBatch(t_.grid.tileSize,
                                           std::max(source_.samples, source_.evaluationsPerPixel));
    // Clustered: the slice bitmasks of a batch fit the shared array (passes/tiled_lighting.h).
    if (slices_ > 0 && !listsOnly_)
        batch = std::min(batch, TP_TL_CLUSTER_MASK_WORDS * 32 / slices_);
    return batch;
}

void TiledLighting::collect(FrameGraph& graph) {
    if (!binning_) return;
    bins_ = binning_->collect(graph);
    candidateCount_ = uint64_t(directional_.size()) * t_.grid.count() + bins_.slots;
    if (listOffsets_.buffer) {
        const std::vector<uint8_t> raw = readbackBuffer(ctx_, listOffsets_);
        t_.listOffsets.resize(size_t(t_.grid.count()) + 1);
        std::memcpy(t_.listOffsets.data(), raw.data(), t_.listOffsets.size() * 4);
    }
}

void TiledLighting::setListOffsets(const std::vector<uint32_t>& offsets) {
    t_.listOffsets = offsets;
    uploadBufferData(ctx_, listOffsets_, offsets.data(), offsets.size() * 4);
}

TileStatTotals sumTileStats(const std::vector<uint32_t>& stats) {
    TileStatTotals t;
    t.tiles = double(stats.size() / 4);
    for (size_t i = 0; i + 3 < stats.size(); i += 4) {
        t.lights += stats[i];
        t.maxLights = std::max(t.maxLights, double(stats[i]));
        t.edges += stats[i + 2];
        t.overflow += stats[i + 3];
    }
    return t;
}

EdgeAndRoughMetal splitDebugImage(const ImageRGBA& dbg) {
    EdgeAndRoughMetal out{ImageRGBA(dbg.width, dbg.height), ImageRGBA(dbg.width, dbg.height)};
    for (size_t i = 0; i < dbg.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c)
            out.edge.rgba[i * 4 + c] = dbg.rgba[i * 4];
        out.roughMetal.rgba[i * 4] = dbg.rgba[i * 4 + 1];
        out.roughMetal.rgba[i * 4 + 1] = dbg.rgba[i * 4 + 2];
        out.edge.rgba[i * 4 + 3] = out.roughMetal.rgba[i * 4 + 3] = 1.0f;
    }
    return out;
}

uint32_t tiledLightBatch(uint32_t tileSize, uint32_t samples) {
    const uint32_t pixels = (tileSize / 8) * (tileSize / 8);
    return std::max(1u, std::min(TP_TL_TILE_LIGHT_CAPACITY, 32768u / (pixels * samples)));
}

void TiledLighting::dispatch(VkCommandBuffer cmd, uint32_t first, uint32_t end) {
    gpu::DrawPush push{0, 0, 0, 0};
    push.TP_TL_LIGHT_FIRST = first;
    push.TP_TL_LIGHT_END = end;
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, t_.grid.tilesX, t_.grid.tilesY, 1);
}

void TiledLighting::record(PassContext& pc) {
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    if (shadowed()) t_.shadows->bind(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_COMPUTE);
    vkCmdBindPipeline(pc.cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    // Binned: batches over each tile's candidates, up to the fullest tile's.
    const uint32_t lights = binned_ ? maxCandidates_ : scene_.lightCount();
    const uint32_t batch = lightBatch();
    batches_ = 0;
    for (uint32_t first = 0; first == 0 || first < lights; first += batch, ++batches_) {
        if (first > 0) {
            // The next batch adds to hdr and the tile statistics that this one wrote.
            memoryBarrier(
                pc.cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        }
        dispatch(pc.cmd, first, std::min(lights, first + batch));
    }
}

} // namespace tp
