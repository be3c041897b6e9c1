#include "core/passes/material_pipelines.h"

#include <algorithm>
#include <array>
#include <map>

#include "core/gpu/context.h"
#include "include/shared.h"

namespace tp {

namespace {

// A material's texture indices in material.glsl's slot order (TP_SPEC_MATERIAL_TEXTURE_FIRST).
using TextureSlots = std::array<int32_t, 5>;

TextureSlots textureSlots(const Material& m) {
    return {m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture, m.occlusionTexture,
            m.emissiveTexture};
}

// Past this many distinct materials in one alpha mode, the rest share one pipeline that reads
// the indices from the material buffer: pipeline creation stays bounded on large scenes.
constexpr size_t kMaxMaterialPipelines = 32;
constexpr TextureSlots kFromMaterial = {TP_TEXTURE_FROM_MATERIAL, TP_TEXTURE_FROM_MATERIAL,
                                        TP_TEXTURE_FROM_MATERIAL, TP_TEXTURE_FROM_MATERIAL,
                                        TP_TEXTURE_FROM_MATERIAL};

} // namespace

MaterialPipelines::~MaterialPipelines() {
    for (VkPipeline p : pipelines_)
        vkDestroyPipeline(ctx_.device, p, nullptr);
}

void MaterialPipelines::create(const SceneGpu& scene, AlphaMode mode,
                               const GraphicsPipelineDesc& base) {
    const std::vector<Material>& materials = scene.scene().materials;
    std::vector<VkPipeline>& byMaterial = byMaterial_[uint32_t(mode)];
    byMaterial.assign(materials.size(), VK_NULL_HANDLE);
    std::map<TextureSlots, VkPipeline> variants;
    auto variant = [&](TextureSlots slots) {
        if (variants.size() >= kMaxMaterialPipelines && !variants.count(slots))
            slots = kFromMaterial;
        if (auto it = variants.find(slots); it != variants.end()) return it->second;
        GraphicsPipelineDesc d = base;
        for (uint32_t i = 0; i < slots.size(); ++i)
            d.specConstants.push_back({TP_SPEC_MATERIAL_TEXTURE_FIRST + i, uint32_t(slots[i])});
        VkPipeline p = createGraphicsPipeline(ctx_, d);
        pipelines_.push_back(p);
        return variants[slots] = p;
    };
    for (const DrawItem* item : scene.drawList(DrawFilter(mode))) {
        if (item->material >= materials.size()) continue; // drawn with the buffer's indices
        VkPipeline& p = byMaterial[item->material];
        if (!p) p = variant(textureSlots(materials[item->material]));
    }
    byMaterial.push_back(variant(kFromMaterial)); // last: for a material index out of range
}

VkPipeline MaterialPipelines::pipeline(AlphaMode mode, uint32_t material) const {
    const std::vector<VkPipeline>& byMaterial = byMaterial_[uint32_t(mode)];
    return byMaterial.empty() ? VK_NULL_HANDLE
                              : byMaterial[std::min<size_t>(material, byMaterial.size() - 1)];
}

} // namespace tp
