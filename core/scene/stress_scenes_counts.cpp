// Stress scenes about light counts and sizes, and the degenerate-geometry scene (built
// directly as a Scene: the glTF loader would repair what this case must feed the GPU).
#include <cmath>
#include <limits>

#include "core/scene/stress_scenes.h"

namespace tp::stress {

using namespace build;
using glm::vec3;

Scene degenerateGeometry() {
    Scene s = stage("stress:degenerate-geometry");
    // A 2 x 2 normal map tilted +-0.3 in x (linear RGBA8): where it is applied, normals lean.
    Texture tex;
    tex.name = "tilted_normals";
    tex.width = tex.height = 2;
    tex.rgba8 = {166, 128, 240, 255, 90, 128, 240, 255, 90, 128, 240, 255, 166, 128, 240, 255};
    s.textures.push_back(tex);
    Material bumpy = plain("bumpy", vec3(0.7f), 0.0f, 1.0f);
    bumpy.normalTexture = 0;
    const uint32_t bump = addMaterial(s, bumpy);
    const float nan = std::numeric_limits<float>::quiet_NaN();

    Mesh nanNormals = meshOf("nan_normals", 1);
    rect(nanNormals, {0.5f, 0.01f, 0}, {2, 0, 0}, {0, 0, -2}, {0, 1, 0});
    nanNormals.normals[0] = vec3(nan);
    nanNormals.normals[2] = vec3(nan, 0, 0);
    Mesh zeroNormals = meshOf("zero_normals", 1);
    rect(zeroNormals, {0.5f, 0, 2.5f}, {0, 1, 0}, {2, 0, 0}, {0, 0, 1});
    for (vec3& n : zeroNormals.normals)
        n = vec3(0.0f);
    // Normal-mapped quads: one without any tangents (the arrays empty), one with zero ones.
    Mesh noTangents = meshOf("no_tangents", bump), zeroTangents = meshOf("zero_tangents", bump);
    rect(noTangents, {-4, 0.01f, 1}, {2, 0, 0}, {0, 0, -2}, {0, 1, 0});
    noTangents.tangents.clear();
    rect(zeroTangents, {-4, 0.5f, -4.99f}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1});
    for (glm::vec4& t : zeroTangents.tangents)
        t = glm::vec4(0.0f);
    // Zero-area triangles inside an ordinary mesh: collinear, repeated vertex, all equal.
    Mesh slivers = meshOf("zero_area", 1);
    rect(slivers, {2.5f, 0.01f, 2}, {1.5f, 0, 0}, {0, 0, -1.5f}, {0, 1, 0});
    const uint32_t b = uint32_t(slivers.positions.size());
    for (vec3 p : {vec3(3, 0.5f, 1), vec3(3.5f, 0.5f, 1), vec3(4, 0.5f, 1)}) {
        slivers.positions.push_back(p);
        slivers.normals.push_back(vec3(0, 0, 1));
        slivers.tangents.push_back(glm::vec4(1, 0, 0, 1));
        slivers.uvs.push_back(glm::vec2(0));
        slivers.colors.push_back(glm::vec4(1));
    }
    for (uint32_t i : {b, b + 1, b + 2, b, b, b + 1, b + 2, b + 2, b + 2, 0u, 0u, 1u})
        slivers.indices.push_back(i);
    s.meshes.insert(s.meshes.end(), {nanNormals, zeroNormals, noTangents, zeroTangents, slivers});
    s.lights.push_back(point({0, 2, 2}, 15.0f, 8.0f));
    s.lights.push_back(point({-3, 1.5f, -3}, 8.0f, 5.0f, vec3(1.0f, 0.8f, 0.6f)));
    finish(s);
    return s;
}

Scene lightCount(uint32_t count) {
    Scene s = stage(count == 0   ? "stress:lights-0"
                    : count == 1 ? "stress:lights-1"
                                 : "stress:lights-65536");
    if (count == 1) s.lights.push_back(point({0.5f, 1.5f, 1}, 20.0f, 8.0f));
    if (count <= 1) {
        finish(s);
        return s;
    }
    // A 256 x 128 grid 5 cm above the floor plus a 256 x 128 grid 5 cm in front of the wall:
    // 65,536 lights of 0.3 m range, 4 cm apart.
    const uint32_t side = 256, rows = count / side / 2;
    for (uint32_t j = 0; j < rows; ++j)
        for (uint32_t i = 0; i < side; ++i) {
            float u = (float(i) + 0.5f) / float(side), v = (float(j) + 0.5f) / float(rows);
            vec3 color(0.3f + 0.7f * u, 0.5f, 1.0f - 0.7f * v);
            s.lights.push_back(point({-5 + 10 * u, 0.05f, -5 + 10 * v}, 0.004f, 0.3f, color));
            s.lights.push_back(point({-5 + 10 * u, 5 * v, -4.95f}, 0.004f, 0.3f, color));
        }
    finish(s);
    return s;
}

Scene lightsWholeScreen() {
    Scene s = stage("stress:lights-whole-screen");
    const vec3 colors[4] = {{1, 0.3f, 0.3f}, {0.3f, 1, 0.3f}, {0.3f, 0.3f, 1}, {1, 1, 0.6f}};
    for (int i = 0; i < 8; ++i)
        s.lights.push_back(point({-4 + float(i), 1 + 0.3f * float(i), -4 + float(i)}, 3.0f, 1000.0f,
                                 colors[i % 4]));
    s.lights.push_back(point(s.camera.position, 5.0f, 500.0f)); // the camera inside its sphere
    Light spot = point({0, 4.5f, 4}, 40.0f, 1000.0f);
    spot.type = LightType::Spot;
    spot.direction = glm::normalize(vec3(0, -1, -0.5f));
    spot.innerConeAngle = 0.5f;
    spot.outerConeAngle = 1.5f; // 172 degrees across: wider than any culling cone test
    s.lights.push_back(spot);
    finish(s);
    return s;
}

Scene lightsSubpixel() {
    Scene s = stage("stress:lights-subpixel");
    // A pixel spans ~9 cm on the floor at 7 m (fov 0.8 rad over 64 rows); each light reaches
    // 2 cm, so most light no pixel centre and a few light one or two.
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 20; ++i) {
            float x = -4.75f + 0.5f * float(i) + 0.013f * float(j % 7),
                  z = -4.75f + 0.5f * float(j) + 0.011f * float(i % 5);
            s.lights.push_back(point({x, 0.005f, z}, 0.05f, 0.02f, vec3(1.0f, 0.9f, 0.7f)));
        }
    s.lights.push_back(sun(vec3(0.3f, -1.0f, -0.4f), 0.2f));
    finish(s);
    return s;
}

} // namespace tp::stress
