#pragma once
// The API-free scene: everything a renderer needs, nothing Vulkan.
// Geometry is flattened to world space at load time (node transforms applied), so every
// renderer draws meshes without a model matrix and the reference sees the same numbers.
// Units: metres; light intensity in candela (point/spot) or lux (directional), as in
// KHR_lights_punctual.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tp {

struct Aabb {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x; }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::vec3 extent() const { return max - min; }
};

// One triangle list with one material. All attribute arrays have positions.size() entries
// (the loader generates normals/tangents when missing, fills uvs with 0 and colors with 1).
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents; // xyz tangent, w = bitangent sign (+1 or -1)
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> colors; // COLOR_0, linear
    std::vector<uint32_t> indices;
    uint32_t material = 0;
    Aabb bounds;
};

enum class AlphaMode : uint32_t { Opaque = 0, Mask = 1, Blend = 2 };

// An RGBA8 texture. srgb says how the texel values are to be decoded (base colour and
// emissive are sRGB, the rest linear); an image used both ways becomes two textures.
struct Texture {
    std::string name;
    uint32_t width = 0;
    uint32_t height = 0;
    bool srgb = false;
    std::vector<uint8_t> rgba8; // width*height*4 bytes
};

constexpr int32_t kNoTexture = -1;

// glTF 2.0 metallic-roughness material.
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f}; // already multiplied by KHR_materials_emissive_strength
    float normalScale = 1.0f;
    float occlusionStrength = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    int32_t baseColorTexture = kNoTexture;         // index into Scene::textures (sRGB)
    int32_t metallicRoughnessTexture = kNoTexture; // G = roughness, B = metallic
    int32_t normalTexture = kNoTexture;
    int32_t occlusionTexture = kNoTexture; // R
    int32_t emissiveTexture = kNoTexture;  // sRGB
};

enum class LightType : uint32_t { Point = 0, Spot = 1, Directional = 2 };

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; // spot and directional: where the light points
    glm::vec3 color{1.0f};
    float intensity = 1.0f;      // candela (point/spot), lux (directional)
    float range = 1.0f;          // point/spot: contribution is exactly zero at and past it
    float innerConeAngle = 0.0f; // radians, spot only
    float outerConeAngle = 0.7853982f;
};

// Perspective camera, reverse-Z. zfar <= 0 means an infinite far plane.
struct Camera {
    glm::vec3 position{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float yfov = 0.8f; // radians
    float znear = 0.05f;
    float zfar = 0.0f;
};

// One attribute accessor whose values the glTF loader replaced (docs/hostile_input.md,
// "Repaired, not refused"): `count` of its `total` elements were replaced as `action` says.
struct SceneRepair {
    std::string attribute; // NORMAL, TANGENT, TEXCOORD_0, COLOR_0
    int accessor = -1;
    size_t count = 0;
    size_t total = 0;
    std::string problem; // what was wrong with them
    std::string action;  // what replaced them
};

struct Scene {
    std::string source;                  // file path, or "builtin:courtyard" etc.
    std::vector<SceneRepair> repairs;    // loader repairs, one per accessor and problem
    std::vector<std::string> extensions; // glTF extensions the loader decoded or applied
    std::vector<Mesh> meshes;
    std::vector<Material> materials; // never empty once loaded (a default material is added)
    std::vector<Texture> textures;
    std::vector<Light> lights; // lights of the file; generated lights replace or add to these
    Camera camera;
    glm::vec3 ambient{0.02f}; // constant ambient radiance (times base colour and occlusion)
    Aabb bounds;

    void computeBounds(); // fills each mesh's bounds and the scene bounds
    size_t triangleCount() const;
    size_t vertexCount() const;
};

// What the renderers plan from: which features this scene and these settings need.
struct SceneFeatures {
    bool blended = false;
    bool masked = false;
    bool normalMaps = false;
    bool emissive = false;
    bool textures = false;
    bool vertexColors = false;
    bool pointLights = false;
    bool spotLights = false;
    bool directionalLights = false;
    uint32_t msaaSamples = 1;
};

SceneFeatures analyzeScene(const Scene& scene, uint32_t msaaSamples);

// Error messages quote files (names, URIs, JSON keys): control characters become spaces and
// bytes that are not UTF-8 become '?', so that a message stays one printable line.
std::string printableLine(const std::string& text);

} // namespace tp
