// The scenes of the stress catalogue's geometric cases (the catalogue is stress_catalogue.cpp,
// the light-count cases' scenes stress_scenes_counts.cpp). Every surface is an axis-aligned
// rectangle with an exact normal unless the case says otherwise (StressCase::freeNormals), so
// the expectations can count G-buffer normal encodings as exact.
#include "core/scene/stress_scenes.h"

#include <cmath>
#include <limits>

namespace tp::stress {

namespace build {

Material plain(const char* name, glm::vec3 base, float metallic, float roughness) {
    Material m;
    m.name = name;
    m.baseColorFactor = glm::vec4(base, 1.0f);
    m.metallicFactor = metallic;
    m.roughnessFactor = roughness;
    return m;
}

uint32_t addMaterial(Scene& s, Material m) {
    s.materials.push_back(std::move(m));
    return uint32_t(s.materials.size() - 1);
}

void rect(Mesh& m, glm::vec3 origin, glm::vec3 u, glm::vec3 v, glm::vec3 n) {
    const uint32_t base = uint32_t(m.positions.size());
    const glm::vec3 corners[4] = {origin, origin + u, origin + u + v, origin + v};
    const glm::vec2 uvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (int i = 0; i < 4; ++i) {
        m.positions.push_back(corners[i]);
        m.normals.push_back(n);
        m.tangents.push_back(glm::vec4(glm::normalize(u), 1.0f));
        m.uvs.push_back(uvs[i]);
        m.colors.push_back(glm::vec4(1.0f));
    }
    // Counter-clockwise seen from n whatever the order of u and v.
    const bool ccw = glm::dot(glm::cross(u, v), n) > 0.0f;
    static constexpr uint32_t front[6] = {0, 1, 2, 0, 2, 3}, back[6] = {0, 2, 1, 0, 3, 2};
    for (uint32_t i : ccw ? front : back)
        m.indices.push_back(base + i);
}

Mesh meshOf(const char* name, uint32_t material) {
    Mesh m;
    m.name = name;
    m.material = material;
    return m;
}

void box(Mesh& m, glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 d = hi - lo, ex(d.x, 0, 0), ey(0, d.y, 0), ez(0, 0, d.z);
    rect(m, lo, ez, ey, {-1, 0, 0});
    rect(m, lo + ex, ez, ey, {1, 0, 0});
    rect(m, lo, ex, ez, {0, -1, 0});
    rect(m, lo + ey, ex, ez, {0, 1, 0});
    rect(m, lo, ex, ey, {0, 0, -1});
    rect(m, lo + ez, ex, ey, {0, 0, 1});
}

Light point(glm::vec3 p, float intensity, float range, glm::vec3 color) {
    Light l;
    l.position = p;
    l.intensity = intensity;
    l.range = range;
    l.color = color;
    return l;
}

Light spot(glm::vec3 p, glm::vec3 direction, float intensity, float range, float inner,
           float outer, glm::vec3 color) {
    Light l = point(p, intensity, range, color);
    l.type = LightType::Spot;
    l.direction = glm::normalize(direction);
    l.innerConeAngle = inner;
    l.outerConeAngle = outer;
    return l;
}

Light sun(glm::vec3 direction, float lux) {
    Light l;
    l.type = LightType::Directional;
    l.direction = glm::normalize(direction);
    l.intensity = lux;
    return l;
}

Scene stage(const char* source) {
    Scene s;
    s.source = source;
    const uint32_t grey = addMaterial(s, plain("grey", glm::vec3(0.5f), 0.0f, 1.0f));
    const uint32_t red = addMaterial(s, plain("red", glm::vec3(0.8f, 0.2f, 0.1f), 0.0f, 0.5f));
    Mesh floor = meshOf("floor", grey), wall = meshOf("wall", grey), crate = meshOf("box", red);
    rect(floor, {-5, 0, 5}, {10, 0, 0}, {0, 0, -10}, {0, 1, 0});
    rect(wall, {-5, 0, -5}, {10, 0, 0}, {0, 5, 0}, {0, 0, 1});
    box(crate, {-2.5f, 0, -2}, {-1.5f, 1, -1});
    s.meshes = {floor, wall, crate};
    s.camera.position = {0, 3, 7};
    s.camera.target = {0, 1, 0};
    s.camera.yfov = 0.8f;
    s.camera.znear = 0.05f;
    s.camera.zfar = 0.0f;
    s.ambient = glm::vec3(0.01f);
    return s;
}

void finish(Scene& s) {
    s.computeBounds();
}

} // namespace build

using namespace build;
using glm::vec3;

Scene tileOverflow() {
    Scene s = stage("stress:tile-overflow");
    // 5,000 lights within 5 cm of one point in front of the wall: every tile that sees the
    // wall near it holds all of them (above the deferred shared list's 4,096).
    Sequence seq{11};
    for (int i = 0; i < 5000; ++i) {
        vec3 p(0.5f + 0.1f * seq.next() - 0.05f, 1.5f + 0.1f * seq.next() - 0.05f,
               -4.5f + 0.1f * seq.next() - 0.05f);
        s.lights.push_back(point(p, 0.01f, 2.5f, vec3(0.5f + 0.5f * seq.next(), 0.8f, 1.0f)));
    }
    finish(s);
    return s;
}

Scene depthDiscontinuity() {
    Scene s = stage("stress:depth-discontinuity");
    s.meshes.pop_back(); // no box: a pole and a far wall
    const uint32_t grey = 0, red = 1;
    Mesh far = meshOf("far_wall", grey), pole = meshOf("pole", red),
         ground = meshOf("far_ground", grey);
    rect(far, {-2000, -5, -1000}, {4000, 0, 0}, {0, 2000, 0}, {0, 0, 1});
    rect(ground, {-2000, -5, 5}, {4000, 0, 0}, {0, 0, -1005}, {0, 1, 0});
    // A 2 cm pole 0.4 m in front of the camera: its tiles span 0.4 m to 1 km.
    box(pole, {0.15f, 0.0f, 6.6f}, {0.17f, 4.0f, 6.62f});
    s.meshes.push_back(far);
    s.meshes.push_back(pole);
    s.meshes.push_back(ground);
    s.camera.target = {0, 2.8f, 0};
    Sequence seq{23};
    for (int i = 0; i < 64; ++i) // near the far wall
        s.lights.push_back(
            point({-600 + 1200 * seq.next(), 300 * seq.next(), -980}, 4.0e4f, 60.0f));
    for (int i = 0; i < 16; ++i) // near the pole and the stage
        s.lights.push_back(point({-1 + 2 * seq.next(), 4 * seq.next(), 6.2f}, 0.5f, 1.0f));
    s.lights.push_back(point({0, 3, 0}, 20.0f, 10.0f));
    finish(s);
    return s;
}

Scene mirrorSpike() {
    Scene s = stage("stress:mirror-spike");
    // Mirror patches (metallic) at the roughness clamp (0.03) on the left and below it (0)
    // on the right; just above the floor and in front of the wall.
    const uint32_t atClamp = addMaterial(s, plain("mirror_0.03", vec3(0.95f), 1.0f, 0.03f));
    const uint32_t below = addMaterial(s, plain("mirror_0", vec3(0.95f), 1.0f, 0.0f));
    Mesh a = meshOf("mirror_at_clamp", atClamp), b = meshOf("mirror_below_clamp", below);
    rect(a, {-2.5f, 0.002f, -2.5f}, {2, 0, 0}, {0, 0, -2}, {0, 1, 0});
    rect(b, {0.5f, 0.002f, -2.5f}, {2, 0, 0}, {0, 0, -2}, {0, 1, 0});
    rect(a, {-2.5f, 0.5f, -4.998f}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1});
    rect(b, {0.5f, 0.5f, -4.998f}, {2, 0, 0}, {0, 2, 0}, {0, 0, 1});
    s.meshes.push_back(a);
    s.meshes.push_back(b);
    s.camera.position = {0, 1.5f, 4};
    s.camera.target = {0, 1, -5};
    for (float x : {-1.5f, 1.5f}) {
        s.lights.push_back(point({x, 0.2f, -4.5f}, 1.0e4f, 20.0f)); // grazing on the floor patches
        s.lights.push_back(
            point({x, 1.5f, 3.0f}, 1.0e4f, 20.0f)); // near-normal on the wall patches
    }
    finish(s);
    return s;
}

Scene lightOnSurface() {
    Scene s = stage("stress:light-on-surface");
    s.lights.push_back(point({1, 0, 1}, 10.0f, 2.0f));        // centre on the floor plane
    s.lights.push_back(point({-1, 0.0001f, 2}, 10.0f, 2.0f)); // 0.1 mm in front of the floor
    s.lights.push_back(point({1, 2, -5.001f}, 10.0f, 2.0f));  // 1 mm behind the wall
    s.lights.push_back(point({-1, 2.5f, -5}, 10.0f, 2.0f));   // centre on the wall plane
    s.lights.push_back(point({-2, 1, -1.5f}, 10.0f, 2.0f));   // on the box's top face
    s.lights.push_back(point({-5, 0, 5}, 10.0f, 2.0f));       // on a floor vertex
    finish(s);
    return s;
}

Scene lightHuggingFar() {
    Scene s;
    s.source = "stress:light-hugging-far";
    const uint32_t grey = addMaterial(s, plain("grey", glm::vec3(0.5f), 0.0f, 1.0f));
    // An 80 x 80 m floor of two triangles: its vertices lie 45-70 m from the eye, the shaded
    // point 22 m away, so a plane-distance computed from a vertex rounds at |p0|, not at |X|.
    Mesh floor = meshOf("floor", grey);
    rect(floor, {-40, 0, 30}, {80, 0, 0}, {0, 0, -80}, {0, 1, 0});
    s.meshes = {floor};
    // At 95 x 63 the ray through pixel (47, 31)'s centre is the view axis: it meets the floor
    // at the target, 5 mm beside a light 0.1 mm above the floor. There n . l is about
    // 0.1 / 5, so a shaded point 1 um off the plane moves the radiance by 1%.
    s.camera.position = {0, 2, 10};
    s.camera.target = {0, 0, -10};
    s.camera.yfov = 0.8f;
    s.camera.znear = 0.05f;
    s.camera.zfar = 0.0f;
    s.ambient = glm::vec3(0.01f);
    s.lights.push_back(point({0.005f, 0.0001f, -10}, 1.0f, 1.0f));
    finish(s);
    return s;
}

Scene beyondHalfFloat() {
    Scene s = stage("stress:beyond-half-float");
    // 1e6 cd 1 m above the floor: radiance 1e6 * 0.5 / pi = 1.6e5 below it, above 65,504
    // within ~0.8 m, ordinary values further away.
    s.lights.push_back(point({0, 1, 0}, 1.0e6f, 10.0f));
    s.lights.push_back(point({-3, 2, 2}, 30.0f, 6.0f, vec3(0.4f, 0.6f, 1.0f)));
    finish(s);
    return s;
}

Scene farFromOrigin() {
    Scene s = stage("stress:far-from-origin");
    Sequence seq{5};
    for (int i = 0; i < 24; ++i)
        s.lights.push_back(
            point({-4.5f + 9 * seq.next(), 0.2f + 2.5f * seq.next(), -4.5f + 9 * seq.next()}, 3.0f,
                  2.5f));
    // Every coordinate 1e6 away (fp32 spacing there: 0.0625). The stage's coordinates are
    // multiples of 1/16, so the geometry and the camera keep their shape exactly; the
    // lights round to the 1/16 grid (the same rounded lights for every pipeline).
    const vec3 t(1.0e6f);
    for (Mesh& m : s.meshes)
        for (vec3& p : m.positions)
            p += t;
    for (Light& l : s.lights)
        l.position += t;
    s.camera.position += t;
    s.camera.target += t;
    finish(s);
    return s;
}

Scene depthPrecision(bool infiniteFar) {
    Scene s = stage(infiniteFar ? "stress:depth-precision-infinite" : "stress:depth-precision");
    s.camera.znear = 1e-3f;
    s.camera.zfar = infiniteFar ? 0.0f : 1e6f;
    const uint32_t white = addMaterial(s, plain("white", vec3(0.9f), 0.0f, 1.0f));
    const uint32_t blue = addMaterial(s, plain("blue", vec3(0.1f, 0.2f, 0.9f), 0.0f, 1.0f));
    Mesh nearBox = meshOf("near_box", white), far = meshOf("far_panel", white),
         farFront = meshOf("far_front", blue);
    // 5 mm cube 2 cm in front of the camera, at the lower left of the view.
    const vec3 eye = s.camera.position;
    nearBox.name = "near_box";
    box(nearBox, eye + vec3(-0.0125f, -0.0105f, -0.025f), eye + vec3(-0.0075f, -0.0055f, -0.02f));
    // Two panels 5e5 m away, 1 m apart in depth (2e-6 relative): the nearer (blue) must win.
    rect(far, {-3e5f, -1e5f, -5e5f}, {6e5f, 0, 0}, {0, 3e5f, 0}, {0, 0, 1});
    rect(farFront, {-1e5f, 0, -5e5f + 1.0f}, {2e5f, 0, 0}, {0, 2e5f, 0}, {0, 0, 1});
    s.meshes.push_back(nearBox);
    s.meshes.push_back(far);
    s.meshes.push_back(farFront);
    // The wall of the stage hides the far panels; lower it so they show above it.
    for (vec3& p : s.meshes[1].positions)
        p.y = std::min(p.y, 1.0f);
    s.lights.push_back(sun(vec3(0.2f, -0.5f, -1.0f), 2.0f));
    s.lights.push_back(point(eye + vec3(0, -0.005f, -0.01f), 0.002f, 0.05f)); // lights the near box
    s.lights.push_back(point({0, 2, 1}, 20.0f, 8.0f));
    finish(s);
    return s;
}

Scene msaaEdges() {
    // White boxes against a near-black wall and the sky, one directional light, rough
    // dielectrics only: edges of the highest contrast, lighting smooth everywhere else.
    Scene s = stage("stress:msaa-edges");
    s.materials[0] = plain("black", vec3(0.02f), 0.0f, 1.0f);
    s.materials[1] = plain("white", vec3(0.9f), 0.0f, 1.0f);
    for (vec3& p : s.meshes[1].positions)
        p.y = std::min(p.y, 2.0f); // sky above the wall
    Mesh more = meshOf("slivers", 1);
    box(more, {0.5f, 0, -1}, {0.55f, 2.5f, -0.95f}); // thin posts: edges on both sides in one pixel
    box(more, {1.5f, 0, 0}, {1.52f, 3.0f, 0.02f});
    box(more, {-1, 0.8f, 1}, {2.5f, 0.83f, 1.03f}); // a thin bar across
    s.meshes.push_back(more);
    s.lights.push_back(sun(vec3(-0.4f, -1.0f, -0.6f), 3.0f));
    s.ambient = glm::vec3(0.0f);
    finish(s);
    return s;
}

} // namespace tp::stress
