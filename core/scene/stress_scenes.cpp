// The stress catalogue and the scenes of its geometric cases; the light-count cases are in
// stress_scenes_counts.cpp. Every surface is an axis-aligned rectangle with an exact normal
// unless the case says otherwise (StressCase::freeNormals), so the expectations can count
// G-buffer normal encodings as exact.
#include "core/scene/stress_scenes.h"

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

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

namespace {

// The catalogue in three parts, each appended in order through `add`.
using AddCase = const std::function<void(StressCase)>&;

// Geometry, depth and precision extremes.
void geometryCases(AddCase add) {
    add({"tile-overflow",
         "5,000 point lights overlap the same tiles (beyond deferred's 4,096-light shared "
         "list)",
         "every light shaded: none dropped, image within the pipeline's precision bound", 96, 64, 1,
         tileOverflow, false, false, false, 5000});
    add({"depth-discontinuity",
         "a 2 cm pole 0.4 m from the eye in front of a wall 1 km away: tiles span 0.4 m to 1 "
         "km",
         "culling efficiency collapses, correctness must not: within the precision bound", 96, 64,
         1, depthDiscontinuity});
    add({"mirror-spike",
         "roughness 0.03 (the clamp) and 0 under 10^4 cd lights, grazing and near-normal "
         "incidence",
         "the spike is finite (roughness clamped), no NaN/Inf, within the bound (G-buffer "
         "roughness quantization counted)",
         96, 64, 1, mirrorSpike});
    add({"light-on-surface",
         "point lights centred on a surface, 0.1 mm in front, 1 mm behind, on a vertex",
         "finite (distance clamped at 1 cm, l = n at distance 0), the back side unlit, within "
         "the bound",
         96, 64, 1, lightOnSurface});
    add({"light-hugging-far",
         "a light 0.1 mm above an 80 m floor, 5 mm beside the point a pixel centre sees 22 m "
         "away (95x63)",
         "the shaded point on the surface to fp32's rounding at its own distance, not at the "
         "triangle's vertices: within the bound",
         95, 63, 1, lightHuggingFar});
    add({"beyond-half-float", "a 10^6 cd light: radiance up to 1.6e5, beyond fp16's 65,504",
         "no NaN; fp32 targets exact within the bound; fp16 targets saturate or overflow only "
         "where the "
         "reference exceeds 65,504 (the report says which); the rest within the bound",
         96, 64, 1, beyondHalfFloat});
    add({"far-from-origin",
         "the lit stage translated by 10^6 units on every axis (fp32 spacing 0.0625)",
         "same data, same vertex shader: within the same bound as at the origin", 96, 64, 1,
         farFromOrigin});
    add({"depth-precision",
         "near 1e-3, far 1e6: a 5 mm cube 2 cm away and panels 5e5 m away 1 m apart",
         "reverse-Z D32 resolves both; depth equals the reference's exactly; within the bound", 96,
         64, 1, [] { return depthPrecision(false); }, true});
    add({"depth-precision-infinite", "as depth-precision with an infinite far plane",
         "reverse-Z D32 resolves both; depth equals the reference's exactly; within the bound", 96,
         64, 1, [] { return depthPrecision(true); }, true});
    add({"degenerate-geometry",
         "zero-area triangles, zero-length and NaN normals, missing and zero tangents under a "
         "normal map",
         "no NaN/Inf (geometric normal fallback, normal map skipped), within the bound", 96, 64, 1,
         degenerateGeometry, false, true});
}

// Light counts and sizes, and MSAA edges.
void lightCases(AddCase add) {
    add({"lights-0", "no light at all: ambient only",
         "ambient exactly as the reference, nothing else", 96, 64, 1,
         [] { return lightCount(0); }});
    add({"lights-1", "a single point light", "within the bound", 96, 64, 1,
         [] { return lightCount(1); }});
    add({"lights-65536", "65,536 point lights (4 cm grid over the floor and the wall), at 48x32",
         "none dropped, within the bound (summation of up to 65,536 terms counted)", 48, 32, 1,
         [] { return lightCount(65536); }});
    add({"lights-whole-screen",
         "lights whose range covers the whole view, one around the camera, a 172-degree spot",
         "every tile holds every light; within the bound", 96, 64, 1, lightsWholeScreen});
    add({"lights-subpixel", "400 lights of 2 cm range 5 mm above the floor, a pixel is ~9 cm there",
         "culling keeps lights smaller than a pixel: within the bound", 96, 64, 1, lightsSubpixel});
    add({"msaa-edges", "4x MSAA, white boxes and thin posts against a near-black wall and the sky",
         "edges resolved per sample like the reference: within the bound", 96, 64, 4, msaaEdges,
         false, false, true});
}

// The stiff cases (stress_scenes_stiff.cpp builds their scenes).
void stiffCases(AddCase add) {
    add({.name = "dynamic-range",
         .stresses = "four lights from 1e3 cd down to 1e-6 cd (10^9) on one screen, no "
                     "ambient: radiance from "
                     "~600 down to ~6e-7 (fp16 subnormals)",
         .expectation = "within the bound per HDR pixel, the dim end too (the tonemapped check "
                        "cannot see it)",
         .build = dynamicRange,
         .hdrChecked = true});
    add({.name = "blended-64",
         .stresses = "64 blended panels (alpha 0.1-0.4) over 240 pixels, lit by two point "
                     "lights and the sun",
         .expectation = "composited back to front like the reference: within the bound, with "
                        "the roundings of "
                        "every blend (each layer, each blended light draw)",
         .build = blendedLayers,
         .blendedLayers = 64});
    add({.name = "lights-range-0",
         .stresses = "18 lights of range 0, 1e-40 and 1.4e-45 (subnormal), points and spots, "
                     "in mid-air, in "
                     "the floor and wall planes, on the box, at the eye; one ordinary light",
         .expectation = "no NaN/Inf, none dropped; each image equals bit for bit the same "
                        "renderer's image "
                        "with their intensity 0; within the bound",
         .build = zeroRangeLights,
         .inertLights = 18});
    add({.name = "camera-in-light",
         .stresses =
             "the eye inside six lights' spheres: behind it, on the near plane, crossing it, 1 "
             "mm "
             "inside the surface, reaching nothing visible, a spot with its apex at the eye",
         .expectation = "each light on exactly the part of the view it reaches, no more, no "
                        "less: within the "
                        "bound",
         .build = cameraInLights});
    add({.name = "spot-zero-cone",
         .stresses = "74 spots with outer = inner = 0, their axes through pixel centres (the "
                     "cosine to the axis "
                     "rounds to 1 or above) or straight down, and one with outer 0 below inner "
                     "0.3; one point light",
         .expectation = "no NaN/Inf; a zero cone lights nothing, not even on its axis: each "
                        "image equals bit "
                        "for bit the same renderer's image with the spots at intensity 0; "
                        "within the bound",
         .build = zeroConeSpots,
         .inertLights = 74});
    add({.name = "spot-hard-edge",
         .stresses = "three spots with inner = outer > 0 (a step at the cone's edge: its 1e-4 "
                     "ramp in the cosine is far thinner than a pixel) across the floor, the box "
                     "and the wall; one point light",
         .expectation = "within the bound on every pixel but those whose points may straddle a "
                        "cone edge, which may differ by the spot's whole light (a per-pixel "
                        "allowance); no NaN/Inf",
         .build = hardSpots});
}

} // namespace

const std::vector<StressCase>& stressCases() {
    static const std::vector<StressCase> cases = [] {
        std::vector<StressCase> c;
        auto add = [&](StressCase sc) { c.push_back(std::move(sc)); };
        geometryCases(add);
        lightCases(add);
        stiffCases(add);
        shadowCases(add);
        return c;
    }();
    return cases;
}

Result<std::vector<const StressCase*>> selectStressCases(const std::string& list) {
    std::vector<const StressCase*> out;
    if (list.empty()) {
        for (const StressCase& c : stressCases())
            out.push_back(&c);
        return out;
    }
    std::vector<std::string> names;
    std::stringstream ss(list);
    std::string item;
    while (std::getline(ss, item, ','))
        names.push_back(item);
    for (const std::string& n : names) {
        bool known = false;
        for (const StressCase& c : stressCases())
            known |= c.name == n;
        if (!known) return Error{"--case: unknown case '" + n + "' (see triptych stress --list)"};
    }
    for (const StressCase& c : stressCases())
        for (const std::string& n : names)
            if (c.name == n) {
                out.push_back(&c);
                break;
            }
    if (out.empty()) return Error{"--case '" + list + "': no case named"};
    return out;
}

} // namespace tp::stress
