#include "core/passes/blended_bounds.h"

#include <cstring>
#include <stdexcept>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "core/gpu/rendering.h"
#include "core/gpuscene/scene_gpu.h"
#include "include/light_assign.h"

namespace tp::la {

BlendedBounds::~BlendedBounds() {
    if (pipeline_) vkDestroyPipeline(ctx_.device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

ResourceHandle BlendedBounds::plan(FrameGraph& graph, const BlendedBoundsConfig& config) {
    if (config.drawnElsewhere && !config.fusable())
        throw std::logic_error("blended bounds: drawn elsewhere at a rate no other pass shares");
    config_ = config;
    const uint32_t tiles = config.grid.count();
    const std::string name = config.opaque ? "centre_bounds" : "blended_bounds";
    bounds_ = graph.createBuffer(
        name, uint64_t(tiles) * 8,
        config.opaque ? "per tile: min and max view distance of the opaque fragments' pixel centres"
                      : "per tile: min and max view distance of the blended fragments shaded");
    graph.addPass(
        name + "_clear", {{bounds_, Use::TransferDst}}, [this, tiles](PassContext& pc) {
            VkBuffer b = pc.buffer(bounds_).buffer;
            vkCmdFillBuffer(pc.cmd, b, 0, VkDeviceSize(tiles) * 4, TP_LA_BLEND_EMPTY);
            vkCmdFillBuffer(pc.cmd, b, VkDeviceSize(tiles) * 4, VkDeviceSize(tiles) * 4, 0u);
        });
    if (config.drawnElsewhere) return bounds_;
    graph.addPass(
        name,
        {{config.depth, Use::DepthTest}, {bounds_, Use::StorageWrite, TP_LA_BLEND_BINDING_BOUNDS}},
        [this](PassContext& pc) { record(pc); });
    return bounds_;
}

void BlendedBounds::prepare(FrameGraph& graph) {
    if (config_.drawnElsewhere) return;
    set_ = graph.createPassSet(config_.opaque ? "centre_bounds" : "blended_bounds");
    layout_ = scene_.createPipelineLayout(set_.layout);
    GraphicsPipelineDesc d;
    // The fragment shader reads the position only (fullInterface: the tests' comparison).
    d.vertexShader = config_.fullInterface ? "scene_vert" : "scene_position_vert";
    d.fragmentShader = std::string("blended_bounds") + config_.inputsSuffix() +
                       (config_.fullInterface ? "_full" : "") + "_frag";
    // The fragment shader reads no material: one pipeline for the opaque and masked draws.
    d.specConstants = scene_.specConstants(config_.opaque ? AlphaMode::Opaque : AlphaMode::Blend);
    d.specConstants.push_back({TP_SPEC_TILE_SIZE, config_.grid.tileSize});
    d.specConstants.push_back(
        {TP_LA_SPEC_BLEND_BY_SUBGROUP, !config_.perFragmentAtomics && ctx_.reducesFragmentsBySubgroup()});
    d.samples = VkSampleCountFlagBits(config_.samples);
    d.sampleShading = config_.sampleShading;
    d.depthWrite = false;
    // Blended: in front of the opaque depth, as the blended pass; opaque: on it, as the opaque
    // shading (no discard there: every sample the prepass kept passes, alpha-tested or not).
    d.depthCompare = config_.opaque ? VK_COMPARE_OP_EQUAL : VK_COMPARE_OP_GREATER;
    d.layout = layout_;
    d.passSet = &set_;
    pipeline_ = createGraphicsPipeline(ctx_, d);
}

void BlendedBounds::record(PassContext& pc) {
    DepthTarget depth{config_.depth, {}, false, true};
    beginRendering(pc, {}, depth);
    scene_.bindSceneSet(pc.cmd, layout_, VK_PIPELINE_BIND_POINT_GRAPHICS);
    vkCmdBindDescriptorSets(pc.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, TP_SET_PASS, 1,
                            &set_.set, 0, nullptr);
    if (config_.opaque) {
        scene_.recordDraws(pc.cmd, layout_, DrawFilter::Opaque, pipeline_);
        scene_.recordDraws(pc.cmd, layout_, DrawFilter::Mask, pipeline_);
    } else {
        scene_.recordDraws(pc.cmd, layout_, DrawFilter::Blend, pipeline_);
    }
    endRendering(pc);
}

std::vector<TileBlendedBounds> unpackBlendedBounds(const std::vector<uint8_t>& bytes,
                                                   uint32_t tiles) {
    std::vector<TileBlendedBounds> out(tiles);
    if (bytes.size() < size_t(tiles) * 8) return out;
    for (uint32_t t = 0; t < tiles; ++t) {
        uint32_t lo, hi;
        std::memcpy(&lo, bytes.data() + size_t(t) * 4, 4);
        std::memcpy(&hi, bytes.data() + size_t(tiles + t) * 4, 4);
        out[t].any = lo < TP_LA_BLEND_EMPTY;
        if (!out[t].any) continue;
        std::memcpy(&out[t].nearDist, &lo, 4);
        std::memcpy(&out[t].farDist, &hi, 4);
    }
    return out;
}

} // namespace tp::la
