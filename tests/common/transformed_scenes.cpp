#include "transformed_scenes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct LocalMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<uint32_t> indices;
};

// An n x n grid of quads in the plane z = 0 over [0, 1]^2, facing +z, moved by `offset`.
LocalMesh quadGrid(uint32_t n, glm::vec3 offset) {
    LocalMesh m;
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i) {
            m.positions.push_back(glm::vec3(float(i) / float(n), float(j) / float(n), 0.0f) +
                                  offset);
            m.normals.push_back({0, 0, 1});
        }
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    return m;
}

// A unit box (counter-clockwise faces seen from outside) moved by `offset`.
LocalMesh box(glm::vec3 offset) {
    LocalMesh m;
    const glm::vec3 n[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& axis : n) {
        const glm::vec3 u = std::abs(axis.x) > 0.5f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 v = glm::cross(axis, u);
        const glm::vec3 centre = offset + glm::vec3(0.5f) + 0.5f * axis;
        const uint32_t base = uint32_t(m.positions.size());
        for (int k = 0; k < 4; ++k) {
            const float su = (k == 1 || k == 2) ? 0.5f : -0.5f, sv = k >= 2 ? 0.5f : -0.5f;
            m.positions.push_back(centre + su * u + sv * v);
            m.normals.push_back(axis);
        }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return m;
}

struct Bin {
    std::vector<uint8_t> bytes;
    json views = json::array(), accessors = json::array();
    int add(const void* data, size_t size, json accessor) {
        while (bytes.size() % 4)
            bytes.push_back(0);
        views.push_back({{"buffer", 0}, {"byteOffset", bytes.size()}, {"byteLength", size}});
        bytes.insert(bytes.end(), (const uint8_t*)data, (const uint8_t*)data + size);
        accessor["bufferView"] = views.size() - 1;
        accessors.push_back(std::move(accessor));
        return int(accessors.size()) - 1;
    }
};

json meshJson(Bin& bin, const LocalMesh& m, int material) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : m.positions)
        lo = glm::min(lo, p), hi = glm::max(hi, p);
    json attributes = {
        {"POSITION", bin.add(m.positions.data(), m.positions.size() * 12,
                             {{"componentType", 5126},
                              {"count", m.positions.size()},
                              {"type", "VEC3"},
                              {"min", {lo.x, lo.y, lo.z}},
                              {"max", {hi.x, hi.y, hi.z}}})},
        {"NORMAL",
         bin.add(m.normals.data(), m.normals.size() * 12,
                 {{"componentType", 5126}, {"count", m.normals.size()}, {"type", "VEC3"}})}};
    const int indices =
        bin.add(m.indices.data(), m.indices.size() * 4,
                {{"componentType", 5125}, {"count", m.indices.size()}, {"type", "SCALAR"}});
    return {{"primitives",
             {{{"attributes", attributes}, {"indices", indices}, {"material", material}}}}};
}

} // namespace

fs::path writeTransformedNodesScene(const fs::path& dir, uint32_t seed, uint32_t nodes,
                                    bool blended) {
    std::mt19937 rng(seed);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    Bin bin;
    json meshes = json::array(), nodeList = json::array(), children = json::array();
    for (uint32_t i = 0; i < nodes; ++i) {
        const glm::vec3 offset(uni(0.5f, 2.5f), uni(-1.5f, 1.0f),
                               uni(-1.0f, 1.0f)); // off the node's origin
        const int material = blended && i % 3 == 2 ? 1 : 0;
        meshes.push_back(meshJson(bin, i % 2 ? box(offset) : quadGrid(2, offset), material));
        // Every node mirrored (one or three negative axes), the scales unequal.
        glm::vec3 scale(uni(0.4f, 1.6f), uni(0.4f, 1.6f), uni(0.4f, 1.6f));
        scale[i % 3] = -scale[i % 3];
        if (i % 4 == 3) scale = -scale;
        const glm::quat q =
            glm::normalize(glm::quat(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1)));
        nodeList.push_back(
            {{"mesh", i},
             {"scale", {scale.x, scale.y, scale.z}},
             {"rotation", {q.x, q.y, q.z, q.w}},
             {"translation", {uni(-2.5f, 2.5f), uni(-1.5f, 1.5f), uni(-2.5f, 2.5f)}}});
        children.push_back(i);
    }
    // Two meshes twice at one transform, as real scenes instance them (SubpassGlass): coincident
    // surfaces that all pass a depth EQUAL test, where the reference shades one of them.
    for (uint32_t i = 0; i < std::min(nodes, 2u); ++i) {
        children.push_back(nodeList.size());
        nodeList.push_back(nodeList[i]);
    }
    // The parent mirrors and stretches everything once more (the world matrix is a product).
    nodeList.push_back(
        {{"children", children}, {"scale", {-1.0, 1.25, 0.8}}, {"translation", {0.5, 0.0, -0.5}}});
    json gltf = {{"asset", {{"version", "2.0"}, {"generator", "triptych tests"}}},
                 {"scene", 0},
                 {"scenes", {{{"nodes", {nodeList.size() - 1}}}}},
                 {"nodes", nodeList},
                 {"meshes", meshes},
                 {"materials",
                  {{{"pbrMetallicRoughness",
                     {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}},
                      {"metallicFactor", 0.0},
                      {"roughnessFactor", 0.5}}}},
                   {{"pbrMetallicRoughness",
                     {{"baseColorFactor", {0.3, 0.6, 0.9, 0.5}},
                      {"metallicFactor", 0.0},
                      {"roughnessFactor", 0.3}}},
                    {"alphaMode", "BLEND"}}}},
                 {"accessors", bin.accessors},
                 {"bufferViews", bin.views},
                 {"buffers", {{{"uri", "scene.bin"}, {"byteLength", bin.bytes.size()}}}}};
    fs::create_directories(dir);
    std::ofstream(dir / "scene.bin", std::ios::binary)
        .write((const char*)bin.bytes.data(), std::streamsize(bin.bytes.size()));
    std::ofstream(dir / "scene.gltf") << gltf.dump(1);
    return dir / "scene.gltf";
}

std::vector<Light> lightsGrazingSurfaces(const Scene& scene, uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
    std::vector<Light> lights;
    while (lights.size() < count) {
        const Mesh& m = scene.meshes[rng() % scene.meshes.size()];
        const size_t t = 3 * (rng() % (m.indices.size() / 3));
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        // Near a corner (both other weights small) or on an edge (one weight 0).
        float u = uni(0, 1), v = uni(0, 1);
        if (rng() % 2)
            u *= 0.05f, v *= 0.05f;
        else
            v = 0;
        if (u + v > 1) u = 1 - u, v = 1 - v;
        const glm::vec3 p = a + u * (b - a) + v * (c - a);
        glm::vec3 dir(uni(-1, 1), uni(-1, 1), uni(-1, 1));
        if (glm::length(dir) < 1e-3f) continue;
        const float d = uni(0.05f, 1.2f);
        Light l;
        l.position = p + d * glm::normalize(dir);
        l.range = d * 1.02f + 1e-3f;
        l.intensity = uni(2.0f, 8.0f);
        l.color = glm::vec3(uni(0.3f, 1), uni(0.3f, 1), uni(0.3f, 1));
        lights.push_back(l);
    }
    return lights;
}

} // namespace tp::test
