#include "core/passes/shadow_maps.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/rendering.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/passes/shadow_cull.h"
#include "core/passes/shadow_raster.h"
#include "core/renderer/renderer.h"

namespace tp {
namespace {

// Whether a world-space box can hold anything the face sees within the light's range: the box
// against the range sphere, then its corners against the face's clip volume (all outside one
// plane: culled). Conservative: a draw that is kept may still put nothing on the face.
bool faceSees(const gpu::ShadowFace& f, glm::vec3 light, float range, const Aabb& box) {
    const glm::vec3 nearest = glm::clamp(light, box.min, box.max);
    if (glm::length(nearest - light) > range) return false;
    uint32_t outside[5] = {0, 0, 0, 0, 0}; // x > w, x < -w, y > w, y < -w, w < near
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                               (c & 4) ? box.max.z : box.min.z);
        const glm::vec4 clip = f.lightProj * glm::vec4(corner - light, 1.0f);
        outside[0] += clip.x > clip.w;
        outside[1] += clip.x < -clip.w;
        outside[2] += clip.y > clip.w;
        outside[3] += clip.y < -clip.w;
        outside[4] += clip.w < f.params.y;
    }
    return std::none_of(outside, outside + 5, [](uint32_t n) { return n == 8; });
}

} // namespace

ShadowMaps::ShadowMaps(GpuContext& ctx, SceneGpu& scene, Residency residency, CullGeometry cull,
                       ShadowRaster raster)
    : ctx_(ctx), scene_(scene), residency_(residency), cullMode_(cull), rasterMode_(raster) {}

ShadowMaps::~ShadowMaps() {
    raster_.reset();
    cull_.reset();
    for (VkPipeline p : {opaque_, mask_})
        if (p) vkDestroyPipeline(ctx_.device, p, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    if (sampler_) vkDestroySampler(ctx_.device, sampler_, nullptr);
    destroyPassSet(ctx_, set_);
}

bool ShadowMaps::enabled() const { return !scene_.shadowPlan().empty(); }

bool ShadowMaps::readsBuffer() const { return raster_ && !cached() && residency_ == Residency::Atlas; }

ResourceHandle ShadowMaps::sampledAtlas() const { return readsBuffer() ? raster_->depth() : map_; }

bool ShadowMaps::cached() const {
    return residency_ == Residency::Atlas && scene_.shadowSettings().cache;
}

std::vector<PassUse> ShadowMaps::sampledUses() const {
    if (!enabled() || cached()) return {};
    if (readsBuffer()) return {{raster_->depth(), Use::StorageRead}};
    return {{map_, Use::Sampled}};
}

std::vector<PassUse> ShadowMaps::perLightUses() const {
    if (!enabled()) return {};
    std::vector<PassUse> uses = {{map_, Use::DepthAttachment}};
    if (cull_)
        for (const PassUse& u : cull_->drawUses()) uses.push_back(u);
    return uses;
}

bool ShadowMaps::stale() {
    if (scene_.shadowGeneration() != generation_) return true; // other lights or sizes, or none
    if (!enabled()) return false;
    const std::vector<gpu::LightGpu> now = shadowedLights();
    if (now.size() == culledLights_.size() &&
        std::memcmp(now.data(), culledLights_.data(), now.size() * sizeof(gpu::LightGpu)) == 0)
        return false;
    // A shadowed light moved: its faces see other draws, the kept maps are stale. Culled in the
    // frame, rows beyond the planned buffers need a new plan.
    if (!cullFaces()) return true;
    if (cached()) renderCached();
    return false;
}

std::vector<gpu::LightGpu> ShadowMaps::shadowedLights() const {
    std::vector<gpu::LightGpu> out;
    for (const ShadowLight& l : scene_.shadowPlan().lights) out.push_back(scene_.lightsGpu()[l.light]);
    return out;
}

ResourceHandle ShadowMaps::plan(FrameGraph& graph) {
    graph_ = &graph;
    generation_ = scene_.shadowGeneration();
    if (!enabled()) return map_ = {};
    const ShadowPlan& p = scene_.shadowPlan();
    const std::string lights = std::to_string(p.lights.size()) + " lights";
    kept_ = Image();
    raster_.reset();
    cull_.reset();
    const bool compute = rasterMode_ == ShadowRaster::Compute;
    if (compute && residency_ == Residency::PerLight)
        throw RendererError("--shadow-raster compute renders the atlas only; one light's map "
                            "(deferred --deferred-lighting volumes, multipass forward) is drawn "
                            "by the hardware: use --shadow-raster hardware");
    if (compute && cullMode_ == CullGeometry::None)
        throw RendererError("--shadow-raster compute rasterizes the meshlets the shadow faces' "
                            "cull keeps: add --cull-geometry frustum (or full)");
    if (cullMode_ != CullGeometry::None) {
        cull_ = std::make_unique<ShadowCull>(ctx_, scene_);
        cullFaces(); // sizes its rows
        if (cached())
            cull_->allocate(graph.owner());
        else
            cull_->plan(graph); // "shadow_cull", before the passes that draw the faces
    }
    if (compute) {
        raster_ = std::make_unique<ShadowComputeRaster>(ctx_, scene_, *cull_);
        raster_->size(p.atlasWidth, p.atlasHeight, faceTriangles_, listCapacity_);
    }
    if (cached()) {
        // Compute: written by a copy, never a depth attachment.
        const VkImageUsageFlags target = compute ? VK_IMAGE_USAGE_TRANSFER_DST_BIT
                                                 : VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
        kept_ = createImage(ctx_, {VK_FORMAT_D32_SFLOAT, p.atlasWidth, p.atlasHeight, 1, VK_SAMPLE_COUNT_1_BIT,
                                   target | VK_IMAGE_USAGE_SAMPLED_BIT},
                            {graph.owner(), "shadow_maps (once)", "shadow_atlas",
                             "shadow maps of " + lights + ", all resident, rendered once and kept"});
        map_ = {};
        if (raster_) raster_->allocate(graph.owner());
    } else if (readsBuffer()) {
        // The consumers read the rasterizer's depth buffer (shadow_sample.glsl:
        // kShadowBuffer): no D32 atlas, no copy.
        map_ = {};
        raster_->plan(graph, {});
        return map_;
    } else if (residency_ == Residency::Atlas) {
        map_ = graph.createImage("shadow_atlas", {VK_FORMAT_D32_SFLOAT, p.atlasWidth, p.atlasHeight,
                                                  VK_SAMPLE_COUNT_1_BIT,
                                                  "shadow maps of " + lights + ", all resident"});
        if (raster_) {
            raster_->plan(graph, map_); // its passes, the last "shadow_maps"
            return map_;
        }
        std::vector<PassUse> uses = {{map_, Use::DepthAttachment}};
        if (cull_)
            for (const PassUse& u : cull_->drawUses()) uses.push_back(u);
        graph.addPass("shadow_maps", uses, [this](PassContext& pc) { recordAtlas(pc); });
    } else {
        // Declared as the consumer's DepthAttachment, sampled between recordLight and endLight.
        map_ = graph.createImage("shadow_map", {VK_FORMAT_D32_SFLOAT, p.localWidth, p.localHeight,
                                                VK_SAMPLE_COUNT_1_BIT,
                                                "one light's shadow map, rendered for each of " + lights,
                                                VK_IMAGE_USAGE_SAMPLED_BIT});
    }
    return map_;
}

SpecConstant ShadowMaps::specConstant() const {
    return {TP_SPEC_SHADOW_LOCAL, residency_ == Residency::PerLight ? 1u : 0u};
}

void ShadowMaps::prepare(FrameGraph& graph) {
    // Its pass is live whatever samples the map (it exports its statistics).
    if (cull_) cull_->prepare(cached() ? nullptr : &graph, graph.owner());
    if (raster_) raster_->prepare(cached() ? nullptr : &graph);
    // Not enabled, or a per-frame atlas no live pass samples (the graph culled it): no set.
    const ResourceHandle sampled = readsBuffer() ? raster_->depth() : map_;
    if (!enabled() || (!cached() && !graph.isAllocated(sampled))) return;
    set_ = createPassSet(ctx_, {{TP_BINDING_SHADOW_FACES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                {TP_BINDING_SHADOW_MAP, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                {TP_BINDING_SHADOW_DEPTH, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}});
    VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    si.magFilter = si.minFilter = VK_FILTER_NEAREST; // texelFetch only
    si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VK_CHECK(vkCreateSampler(ctx_.device, &si, nullptr, &sampler_));
    writeBufferDescriptor(ctx_, set_.set, TP_BINDING_SHADOW_FACES, scene_.shadowFaces());
    // The binding the shaders do not read is still written (with the faces, or a 1x1 map).
    writeBufferDescriptor(ctx_, set_.set, TP_BINDING_SHADOW_DEPTH,
                          readsBuffer() ? graph.buffer(sampled).buffer : scene_.shadowFaces());
    writeImageDescriptor(ctx_, set_.set, TP_BINDING_SHADOW_MAP,
                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                         cached()        ? kept_.view
                         : readsBuffer() ? raster_->standInMap(graph.owner())
                                         : graph.image(map_).view,
                         VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, sampler_);
    layout_ = scene_.createPipelineLayout(VK_NULL_HANDLE, set_.layout);
    if (raster_) { // no graphics pipelines: the faces are rasterized in compute
        cullFaces();
        if (cached()) renderCached();
        return;
    }
    GraphicsPipelineDesc d;
    d.layout = layout_;
    d.vertexShader = "shadow_vert";
    d.specConstants = scene_.specConstants(AlphaMode::Opaque);
    opaque_ = createGraphicsPipeline(ctx_, d);
    if (scene_.hasDraws(DrawFilter::Mask)) {
        d.vertexShader = "shadow_mask_vert";
        d.fragmentShader = "prepass_mask_frag";
        d.specConstants = scene_.specConstants(AlphaMode::Mask);
        mask_ = createGraphicsPipeline(ctx_, d);
    }
    cullFaces();
    if (cached()) renderCached();
}

void ShadowMaps::apply(std::string& shader, std::vector<SpecConstant>& spec) const {
    if (!enabled()) return;
    const size_t stage = shader.rfind('_');
    shader.insert(stage == std::string::npos ? shader.size() : stage, "_shadow");
    spec.push_back(specConstant());
    spec.push_back({TP_SPEC_SHADOW_BUFFER, readsBuffer() ? 1u : 0u});
    spec.push_back({TP_SPEC_SHADOW_ATLAS_WIDTH, std::max(1u, scene_.shadowPlan().atlasWidth)});
}

void ShadowMaps::bind(VkCommandBuffer cmd, VkPipelineLayout layout, VkPipelineBindPoint point) const {
    if (!set_.set) return;
    vkCmdBindDescriptorSets(cmd, point, layout, TP_SET_SHADOW, 1, &set_.set, 0, nullptr);
}

bool ShadowMaps::cullFaces() {
    const ShadowPlan& plan = scene_.shadowPlan();
    faceDraws_.assign(plan.faces.size(), {});
    faceDrawCount_ = faceTriangles_ = 0;
    std::vector<const DrawItem*> draws = scene_.drawList(DrawFilter::Opaque);
    for (const DrawItem* d : scene_.drawList(DrawFilter::Mask)) draws.push_back(d);
    for (uint32_t face = 0; face < plan.faces.size(); ++face) {
        const gpu::ShadowFace& f = plan.faces[face];
        const gpu::LightGpu& light = scene_.lightsGpu()[f.atlas.w]; // world space, as the boxes
        for (const DrawItem* d : draws)
            if (faceSees(f, light.position, light.range, d->bounds)) {
                faceDraws_[face].push_back(d);
                faceTriangles_ += double(d->indexCount / 3);
            }
        faceDrawCount_ += double(faceDraws_[face].size());
    }
    culledLights_ = shadowedLights();
    return !cull_ || cull_->setRows(faceDraws_);
}

// One face's draws: whole, or (culled) each as the indirect draws of its kept meshlets.
void ShadowMaps::recordFaceDraws(VkCommandBuffer cmd, uint32_t face, VkPipeline& bound) {
    const std::vector<const DrawItem*>& draws = faceDraws_[face];
    for (uint32_t k = 0; k < draws.size(); ++k) {
        const DrawItem* d = draws[k];
        const VkPipeline p = d->alphaMode == AlphaMode::Mask ? mask_ : opaque_;
        if (p != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = p);
        const gpu::DrawPush push{d->material, face, 0, 0};
        vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_ALL, 0, sizeof(push), &push);
        if (cull_)
            cull_->recordDraw(cmd, cull_->firstRowOf(face) + k);
        else
            vkCmdDrawIndexed(cmd, d->indexCount, 1, d->firstIndex, d->vertexOffset, 0);
    }
}

// The faces as squares of the map (positive-height viewports: texel = origin + (ndc * 0.5 +
// 0.5) * edge, as shadow_sample.glsl reads them), every draw that may reach each.
void ShadowMaps::recordFaces(VkCommandBuffer cmd, uint32_t firstFace, uint32_t faceCount, bool local) {
    scene_.bindSceneSet(cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    bind(cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    if (cull_)
        scene_.bindMeshletIndexBuffer(cmd);
    else
        scene_.bindIndexBuffer(cmd);
    vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE); // a map sees both sides of every surface
    VkPipeline bound = VK_NULL_HANDLE;
    for (uint32_t face = firstFace; face < firstFace + faceCount; ++face) {
        const gpu::ShadowFace& f = scene_.shadowPlan().faces[face];
        const glm::uvec2 origin = local ? glm::uvec2(f.local) : glm::uvec2(f.atlas);
        const VkViewport vp{float(origin.x), float(origin.y), float(f.atlas.z), float(f.atlas.z), 0.0f, 1.0f};
        const VkRect2D sc{{int32_t(origin.x), int32_t(origin.y)}, {f.atlas.z, f.atlas.z}};
        vkCmdSetViewport(cmd, 0, 1, &vp);
        vkCmdSetScissor(cmd, 0, 1, &sc);
        recordFaceDraws(cmd, face, bound);
    }
}

void ShadowMaps::recordAtlas(PassContext& pc) {
    beginRendering(pc, {}, DepthTarget{map_, {}, true, false, 0.0f});
    recordFaces(pc.cmd, 0, uint32_t(scene_.shadowPlan().faces.size()), false);
    endRendering(pc);
}

bool ShadowMaps::shadowed(uint32_t light) const {
    return light < scene_.shadingLights().size() && scene_.shadingLights()[light].shadow != 0;
}

namespace {
// The map between its two uses: rendered (depth attachment) -> sampled (toRead), or back;
// `discard`: back from nothing (its old contents are not kept).
void depthBarrier(VkCommandBuffer cmd, VkImage image, bool toRead, bool discard = false) {
    const VkPipelineStageFlags2 tests = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                        VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    const VkPipelineStageFlags2 shaders = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    const VkAccessFlags2 write = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                 VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = toRead ? tests : shaders;
    b.srcAccessMask = toRead ? write : VK_ACCESS_2_NONE;
    b.dstStageMask = toRead ? shaders : tests;
    b.dstAccessMask = toRead ? VK_ACCESS_2_SHADER_SAMPLED_READ_BIT : write;
    b.oldLayout = toRead    ? VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL
                  : discard ? VK_IMAGE_LAYOUT_UNDEFINED
                            : VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL;
    b.newLayout = toRead ? VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}
} // namespace

void ShadowMaps::recordLight(PassContext& pc, uint32_t light) {
    if (!shadowed(light)) return;
    const uint32_t first = scene_.shadingLights()[light].shadow - 1;
    const uint32_t count = uint32_t(scene_.shadowPlan().faces[first].params.z);
    beginRendering(pc, {}, DepthTarget{map_, {}, true, false, 0.0f});
    recordFaces(pc.cmd, first, count, true);
    endRendering(pc);
    depthBarrier(pc.cmd, pc.image(map_).image, true);
}

// The kept atlas, outside any frame: cleared, every face rendered, left readable, with two
// timestamps around it. The queue is idle afterwards (submitAndWait), so the frames that sample
// it need no barrier of their own.
void ShadowMaps::renderCached() {
    VkQueryPoolCreateInfo qi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qi.queryCount = 2;
    VkQueryPool pool;
    VK_CHECK(vkCreateQueryPool(ctx_.device, &qi, nullptr, &pool));
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
        vkCmdResetQueryPool(cmd, pool, 0, 2);
        if (raster_) {
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool, 0);
            renderCachedCompute(cmd);
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool, 1);
            return;
        }
        depthBarrier(cmd, kept_.image, false, true); // the old maps are discarded
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool, 0);
        if (cull_) {
            // Outside the graph: the last render's indirect reads before this one's writes, and
            // the writes before this render's draws read them.
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                          VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
            cull_->record(cmd);
            memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                          VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
        }
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = kept_.view;
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {0.0f, 0}; // reverse-Z: nothing in the way
        VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
        ri.renderArea = {{0, 0}, {kept_.desc.width, kept_.desc.height}};
        ri.layerCount = 1;
        ri.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &ri);
        recordFaces(cmd, 0, uint32_t(scene_.shadowPlan().faces.size()), false);
        vkCmdEndRendering(cmd);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool, 1);
        depthBarrier(cmd, kept_.image, true);
    });
    uint64_t ticks[2] = {0, 0};
    VK_CHECK(vkGetQueryPoolResults(ctx_.device, pool, 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    vkDestroyQueryPool(ctx_.device, pool, nullptr);
    keptRenderMs_ = double(ticks[1] - ticks[0]) * ctx_.caps.timestampPeriodNs * 1e-6;
    ++keptRenders_;
    if (cull_) cull_->collect(nullptr);
    if (raster_) raster_->collect(nullptr);
}

// The kept atlas in compute: the cull (the last render's reads of its commands before its
// writes), its writes before the rasterizer reads them, then the rasterizer's passes and the
// copy (shadow_raster.h), which leave the atlas readable.
void ShadowMaps::renderCachedCompute(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    cull_->record(cmd);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    raster_->recordOwn(cmd, kept_.image);
}

void ShadowMaps::collect(FrameGraph& graph) {
    if (cull_ && !cached()) cull_->collect(&graph);
    if (raster_ && !cached()) raster_->collect(&graph);
}

void ShadowMaps::endLight(PassContext& pc) { depthBarrier(pc.cmd, pc.image(map_).image, false); }

std::vector<std::pair<std::string, double>> ShadowMaps::counters() const {
    if (!enabled()) return {};
    const ShadowPlan& p = scene_.shadowPlan();
    const bool atlas = residency_ == Residency::Atlas;
    std::vector<std::pair<std::string, double>> c = {
        {"shadowed_lights", double(p.lights.size())},
        {"shadow_faces", double(p.faces.size())},
        {"shadow_map_bytes", double(atlas ? p.atlasBytes() : p.localBytes())},
        {"shadow_map_renders_per_frame", cached() ? 0.0 : atlas ? 1.0 : double(p.lights.size())},
        {"shadow_face_draws", faceDrawCount_},
        {"shadow_triangles", faceTriangles_},
        {"shadow_maps_cached", cached() ? 1.0 : 0.0}};
    if (cull_)
        for (const auto& kv : cull_->counters()) c.push_back(kv);
    if (raster_)
        for (const auto& kv : raster_->counters()) c.push_back(kv);
    if (cached()) {
        c.push_back({"shadow_maps_render_ms", keptRenderMs_});
        c.push_back({"shadow_maps_renders", double(keptRenders_)});
    }
    return c;
}

} // namespace tp
