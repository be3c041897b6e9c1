#include "core/calibrate/material_fetches.h"

#include <algorithm>

namespace tp {

int materialFetches(const Scene& scene, const Material& m) {
    const int textures = int(scene.textures.size());
    int n = 0;
    // Not the normal map: material.glsl samples it only where the tangent is not degenerate.
    for (int32_t slot :
         {m.baseColorTexture, m.metallicRoughnessTexture, m.occlusionTexture, m.emissiveTexture})
        n += slot >= 0 && slot < textures; // material.glsl: an index out of range samples nothing
    return n;
}

double minMaterialFetches(const Scene& scene, const std::vector<const DrawItem*>& draws) {
    if (draws.empty()) return 0;
    int fewest = 5;
    for (const DrawItem* d : draws)
        fewest = std::min(fewest, materialFetches(scene, scene.materials.at(d->material)));
    return fewest;
}

PassOpWork materialFetchWork(const SceneGpu& scene, const std::string& pass,
                             std::initializer_list<DrawFilter> filters, PassLightWork::Base base,
                             double share) {
    std::vector<const DrawItem*> draws;
    for (DrawFilter f : filters) {
        const std::vector<const DrawItem*> some = scene.drawList(f);
        draws.insert(draws.end(), some.begin(), some.end());
    }
    return {pass,
            PassOpWork::Kind::TextureFetches,
            base,
            minMaterialFetches(scene.scene(), draws) * share,
            false,
            "the fewest textures of the draws' materials, per " +
                std::string(base == PassLightWork::Base::Fragments ? "fragment"
                                                                   : "pixel with geometry") +
                (share < 1 ? " (half the fragments: the others sample none)" : "")};
}

} // namespace tp
