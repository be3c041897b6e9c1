#include "core/scene/scene.h"

namespace tp {

void Scene::computeBounds() {
    bounds = Aabb{};
    for (Mesh& mesh : meshes) {
        mesh.bounds = Aabb{};
        for (const glm::vec3& p : mesh.positions)
            mesh.bounds.extend(p);
        if (!mesh.bounds.empty()) bounds.extend(mesh.bounds);
    }
}

size_t Scene::triangleCount() const {
    size_t n = 0;
    for (const Mesh& mesh : meshes)
        n += mesh.indices.size() / 3;
    return n;
}

size_t Scene::vertexCount() const {
    size_t n = 0;
    for (const Mesh& mesh : meshes)
        n += mesh.positions.size();
    return n;
}

SceneFeatures analyzeScene(const Scene& scene, uint32_t msaaSamples) {
    SceneFeatures f;
    f.msaaSamples = msaaSamples;
    for (const Mesh& mesh : scene.meshes) {
        const Material& m = scene.materials.at(mesh.material);
        f.blended |= m.alphaMode == AlphaMode::Blend;
        f.masked |= m.alphaMode == AlphaMode::Mask;
        f.normalMaps |= m.normalTexture != kNoTexture;
        f.emissive |= m.emissiveFactor != glm::vec3(0.0f);
        f.textures |= m.baseColorTexture != kNoTexture ||
                      m.metallicRoughnessTexture != kNoTexture || m.normalTexture != kNoTexture ||
                      m.occlusionTexture != kNoTexture || m.emissiveTexture != kNoTexture;
        for (const glm::vec4& c : mesh.colors) {
            if (c != glm::vec4(1.0f)) {
                f.vertexColors = true;
                break;
            }
        }
    }
    for (const Light& light : scene.lights) {
        f.pointLights |= light.type == LightType::Point;
        f.spotLights |= light.type == LightType::Spot;
        f.directionalLights |= light.type == LightType::Directional;
    }
    return f;
}

std::string printableLine(const std::string& text) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
        const uint8_t c = uint8_t(text[i]);
        size_t length = c < 0x80         ? 1
                        : (c >> 5) == 6  ? 2
                        : (c >> 4) == 14 ? 3
                        : (c >> 3) == 30 ? 4
                                         : 0;
        bool valid = length > 0 && i + length <= text.size();
        for (size_t k = 1; valid && k < length; ++k)
            valid = (uint8_t(text[i + k]) >> 6) == 2;
        if (!valid) {
            out += '?';
            ++i;
        } else if (length == 1) {
            out += c < 0x20 || c == 0x7f ? ' ' : char(c);
            ++i;
        } else {
            out.append(text, i, length);
            i += length;
        }
    }
    return out;
}

} // namespace tp
