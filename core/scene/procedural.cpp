// The built-in courtyard (see procedural.h): materials, floor, walls, planters and the camera
// here; the colonnades in procedural_colonnade.cpp, the textures in procedural_textures.cpp.
#include "core/scene/procedural.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/scene/mesh_builder.h"
#include "core/scene/procedural_parts.h"
#include "core/scene/procedural_textures.h"

namespace tp {

namespace procgen {

Storey storey(int index) {
    if (index == 0) return {0, 0.0f, 0.25f, 0.48f, 0.3f, 3.0f, 0.25f, 0.2f, 0.5f, 0.3f, 6.0f, 6.4f};
    return {1, 6.4f, 0.2f, 0.42f, 0.25f, 2.5f, 0.25f, 0.2f, 0.42f, 0.26f, 11.9f, 12.3f};
}

Tessellation tessellation(float detail) {
    const float g = std::pow(std::clamp(detail, 0.0f, 16.0f), 0.75f);
    // Truncated rather than rounded, so that test-sized scenes drop the small mouldings.
    auto n = [g](float full, int least) { return std::max(least, int(full * g + 1e-3f)); };
    Tessellation t;
    t.columnSegments = n(44, 6);
    t.shaftRows = n(10, 1);
    t.baseRows = n(7, 0);
    t.capitalRows = n(5, 0);
    t.archSegments = 4 * n(8, 1);
    t.rimRows = n(6, 0);
    t.balusterSegments = n(10, 4);
    t.balusterRows = n(8, 1);
    t.balustersPerBay = n(9, 2);
    t.clothU = n(40, 2);
    t.clothV = n(28, 2);
    t.floorX = n(30, 1);
    t.floorZ = n(60, 1);
    t.potSegments = n(24, 6);
    t.potRows = n(8, 2);
    t.rodSegments = n(12, 4);
    return t;
}

namespace {

using glm::vec2;
using glm::vec3;

CourtyardMaterials addMaterials(Scene& scene, const CourtyardTextures& tx) {
    auto add = [&](Material m) {
        scene.materials.push_back(std::move(m));
        return uint32_t(scene.materials.size() - 1);
    };
    auto textured = [](const char* name, int32_t base, int32_t mr, int32_t normal) {
        Material m;
        m.name = name;
        m.metallicFactor = 1.0f; // the metallic-roughness texture holds metallic = 0
        m.baseColorTexture = base;
        m.metallicRoughnessTexture = mr;
        m.normalTexture = normal;
        return m;
    };
    auto plain = [](const char* name, vec3 color, float metallic, float roughness) {
        Material m;
        m.name = name;
        m.baseColorFactor = glm::vec4(color, 1.0f);
        m.metallicFactor = metallic;
        m.roughnessFactor = roughness;
        return m;
    };
    CourtyardMaterials cm;
    cm.floor = add(textured("floor_stone", tx.floorBase, tx.floorMr, tx.floorNormal));
    cm.brick = add(textured("brick", tx.brickBase, tx.brickMr, tx.brickNormal));
    Material stone = plain("stone", vec3(1.0f), 0.0f, 0.65f);
    stone.baseColorTexture = tx.stoneBase;
    cm.stone = add(stone);
    const char* clothNames[3] = {"cloth_red", "cloth_green", "cloth_blue"};
    const int32_t clothTex[3] = {tx.clothRed, tx.clothGreen, tx.clothBlue};
    for (int i = 0; i < 3; ++i) {
        Material c = plain(clothNames[i], vec3(1.0f), 0.0f, 0.9f);
        c.baseColorFactor.a = 0.65f + 0.05f * float(i);
        c.baseColorTexture = clothTex[i];
        c.alphaMode = AlphaMode::Blend;
        c.doubleSided = true;
        cm.cloth[i] = add(c);
    }
    Material lamp = plain("lamp", vec3(1.0f, 0.9f, 0.75f), 0.0f, 0.4f);
    lamp.emissiveFactor = vec3(4.0f, 3.0f, 1.8f);
    cm.lamp = add(lamp);
    // Alpha-tested and seen from both sides: the grille's bars, the leaves.
    auto cutout = [&](const char* name, float metallic, float roughness, int32_t texture) {
        Material m = plain(name, vec3(1.0f), metallic, roughness);
        m.baseColorTexture = texture;
        m.alphaMode = AlphaMode::Mask;
        m.alphaCutoff = 0.5f;
        m.doubleSided = true;
        return m;
    };
    cm.grille = add(cutout("iron_grille", 1.0f, 0.5f, tx.grille));
    cm.foliage = add(cutout("foliage", 0.0f, 0.7f, tx.foliage));
    cm.terracotta = add(plain("terracotta", vec3(0.62f, 0.30f, 0.18f), 0.0f, 0.8f));
    cm.iron = add(plain("iron", vec3(0.30f, 0.30f, 0.32f), 1.0f, 0.45f));
    return cm;
}

// Openings of the end walls, in wall coordinates (x from the wall's left end, y up). The end
// walls run into the back walls, so no two faces meet in one plane.
constexpr float kEndWidth = 2.0f * kHalfX;
constexpr std::array<Rect, 8> kEndOpenings = {{
    {13.0f, 0.0f, 17.0f, 5.0f}, // central gate
    {1.4f, 0.0f, 3.0f, 3.2f},   // doors under the galleries
    {27.0f, 0.0f, 28.6f, 3.2f},
    {1.4f, 6.4f, 3.0f, 9.0f}, // doors onto the galleries
    {27.0f, 6.4f, 28.6f, 9.0f},
    {9.0f, 7.0f, 11.5f, 10.0f}, // windows, with grilles
    {18.5f, 7.0f, 21.0f, 10.0f},
    {14.0f, 7.5f, 16.0f, 10.5f},
}};
constexpr int kFirstWindow = 5; // the openings before it are doors, with a room behind each

void addWalls(Scene& scene, const Tessellation& t, const CourtyardMaterials& m) {
    MeshBuilder floor("floor", m.floor);
    const float hx = kHalfX, hz = kHalfZ;
    addQuad(floor, vec3(-hx, 0, hz), vec3(hx, 0, hz), vec3(hx, 0, -hz), vec3(-hx, 0, -hz),
            vec2(-hx, -hz) / kFloorTex, vec2(hx, hz) / kFloorTex, t.floorX, t.floorZ);
    scene.meshes.push_back(floor.finish());

    const float in = kHalfX - kWallT, inZ = kEndZ;
    const vec3 up(0, 1, 0);
    MeshBuilder back("walls_back", m.brick);
    addWall(back, vec3(in, 0, -hz), vec3(0, 0, 1), up, 2 * hz, kHeight, kWallT, {}, kBrickTex);
    addWall(back, vec3(-in, 0, hz), vec3(0, 0, -1), up, 2 * hz, kHeight, kWallT, {}, kBrickTex);
    scene.meshes.push_back(back.finish());

    MeshBuilder ends("walls_end", m.brick), grilles("grilles", m.grille);
    MeshBuilder rooms("rooms", m.brick);
    for (float dir : {-1.0f, 1.0f}) { // far (-z) end, then near (+z) end
        vec3 right(-dir, 0, 0), origin(dir * kHalfX, 0, dir * inZ);
        addWall(ends, origin, right, up, kEndWidth, kHeight, kWallT, kEndOpenings, kBrickTex);
        for (size_t i = kFirstWindow; i < kEndOpenings.size(); ++i) {
            const Rect& r = kEndOpenings[i];
            vec3 o = origin + vec3(0, 0, dir * 0.5f * kWallT);
            vec3 p0 = o + right * r.x0 + up * r.y0, p1 = o + right * r.x1 + up * r.y0;
            vec3 p2 = o + right * r.x1 + up * r.y1, p3 = o + right * r.x0 + up * r.y1;
            addQuad(grilles, p0, p1, p2, p3, vec2(0, 1), vec2(1, 0));
        }
        for (int i = 0; i < kFirstWindow; ++i) {
            const Rect& r = kEndOpenings[size_t(i)];
            float x0 = origin.x + right.x * (r.x0 - 0.6f), x1 = origin.x + right.x * (r.x1 + 0.6f);
            float z0 = dir * (kEndZ + kWallT), z1 = dir * kHalfZ;
            vec3 lo(std::min(x0, x1), r.y0, std::min(z0, z1));
            vec3 hi(std::max(x0, x1), r.y1 + 0.6f, std::max(z0, z1));
            uint32_t skip =
                (dir < 0 ? kSkipPlusZ : kSkipMinusZ) | (r.y0 == 0.0f ? kSkipBottom : 0u);
            addBox(rooms, lo, hi, kBrickTex, skip, true); // the courtyard floor runs under it
        }
    }
    scene.meshes.push_back(ends.finish());
    scene.meshes.push_back(grilles.finish());
    scene.meshes.push_back(rooms.finish());
}

// Terracotta pots with a bush of crossed cut-out leaf cards, along the colonnades.
void addPlanters(Scene& scene, const Tessellation& t, const CourtyardMaterials& m) {
    static constexpr std::array<vec2, 8> pot = {{{0.30f, 0.0f},
                                                 {0.36f, 0.08f},
                                                 {0.38f, 0.45f},
                                                 {0.46f, 0.62f},
                                                 {0.48f, 0.70f},
                                                 {0.44f, 0.72f},
                                                 {0.42f, 0.66f},
                                                 {0.02f, 0.64f}}};
    MeshBuilder pots("planters", m.terracotta), leaves("foliage", m.foliage);
    for (float x : {-8.0f, 8.0f}) {
        for (float z : {-18.0f, -2.0f, 14.0f}) {
            vec3 c(x, 0, z);
            addLathe(pots, c, pot, t.potSegments, t.potRows, 1.0f);
            for (int k = 0; k < 3; ++k) {
                float a = float(k) * 1.0471976f + 0.3f * z;
                vec3 d(0.8f * std::cos(a), 0, 0.8f * std::sin(a));
                vec3 lo = c + vec3(0, 0.55f, 0), hi = c + vec3(0, 2.15f, 0);
                addQuad(leaves, lo - d, lo + d, hi + d, hi - d, vec2(0, 1), vec2(1, 0));
            }
        }
    }
    scene.meshes.push_back(pots.finish());
    scene.meshes.push_back(leaves.finish());
}

} // namespace
} // namespace procgen

Scene makeCourtyard(const CourtyardOptions& options) {
    using namespace procgen;
    Scene scene;
    scene.source = "builtin:courtyard";
    const CourtyardTextures tx = addCourtyardTextures(scene.textures);
    const CourtyardMaterials m = addMaterials(scene, tx);
    const Tessellation t = tessellation(options.detail);
    addWalls(scene, t, m);
    for (float side : {-1.0f, 1.0f})
        for (int storey = 0; storey < 2; ++storey)
            addColonnade(scene, t, m, side, storey);
    addPlanters(scene, t, m);
    scene.camera.position = glm::vec3(0.0f, 1.8f, kEndZ - 2.0f);
    scene.camera.target = glm::vec3(0.0f, 2.6f, -kHalfZ);
    scene.camera.yfov = 1.0f;
    scene.camera.znear = 0.05f;
    scene.camera.zfar = 0.0f;
    scene.ambient = glm::vec3(0.03f);
    scene.computeBounds();
    return scene;
}

Result<Scene> makeBuiltinScene(const std::string& name) {
    if (name == "courtyard") return makeCourtyard({1.0f});
    if (name == "courtyard-small") return makeCourtyard({0.08f});
    return Error{"unknown built-in scene '" + name + "' (valid: courtyard, courtyard-small)"};
}

} // namespace tp
