// Stress scenes at the edges of the light model and of compositing (issue 29, item 7): a
// 10^9 range of light intensities on one screen, 64 blended layers over one pixel, lights of
// range 0 and of subnormal range, the camera inside lights' spheres, spot lights with a
// zero cone. Surfaces stay axis-aligned (exact G-buffer normals) as in the other cases.
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene/stress_scenes.h"

namespace tp::stress {

using namespace build;
using glm::vec3;

namespace {

// The world-space direction of the ray through pixel (px, py)'s centre of a w x h image of
// the scene's camera (right-handed view, y up, rows from the top): where a spot's axis must
// point for a pixel's shaded point to lie on it, within rounding.
vec3 pixelRay(const Camera& c, uint32_t w, uint32_t h, uint32_t px, uint32_t py) {
    const glm::dmat4 view = glm::lookAt(
        glm::dvec3(0.0), glm::dvec3(c.target) - glm::dvec3(c.position), glm::dvec3(c.up));
    const double t = std::tan(0.5 * double(c.yfov)), aspect = double(w) / double(h);
    const double x = 2.0 * (px + 0.5) / w - 1.0, y = 1.0 - 2.0 * (py + 0.5) / h;
    const glm::dvec3 viewRay(x * t * aspect, y * t, -1.0);
    return vec3(glm::normalize(glm::dvec3(glm::inverse(view) * glm::dvec4(viewRay, 0.0))));
}

} // namespace

Scene dynamicRange() {
    Scene s = stage("stress:dynamic-range");
    // No ambient: a pixel a dim light reaches holds that light's term and nothing else.
    s.ambient = vec3(0.0f);
    // Four lights 10^3 apart in intensity, 1e3 cd down to 1e-6 cd (10^9), each lighting its
    // own disc of the floor (range 1.2 m, 2.5 m apart, 0.5 m high): radiance ~600 under the
    // brightest, ~6e-7 under the dimmest (fp16 subnormals, whose spacing is 6e-8).
    const float intensity[4] = {1.0e3f, 1.0f, 1.0e-3f, 1.0e-6f};
    for (int i = 0; i < 4; ++i)
        s.lights.push_back(point({-3.75f + 2.5f * float(i), 0.5f, 1.0f}, intensity[i], 1.2f));
    finish(s);
    return s;
}

Scene blendedLayers() {
    Scene s = stage("stress:blended-64");
    // 64 blended panels facing the camera between the wall and the box, 3 cm apart in depth,
    // each 1 cm smaller on every side than the one behind it: 240 pixels at the centre of
    // the view see all 64 layers over the wall, the edges fewer. Alpha 0.1 to 0.4 and
    // colours cycle, so no layer hides the ones behind it and every rounding of the
    // composite reaches the pixel.
    const vec3 colors[4] = {
        {0.9f, 0.3f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.4f, 0.9f}, {0.9f, 0.9f, 0.8f}};
    uint32_t layerMaterial[4];
    for (int c = 0; c < 4; ++c) {
        Material m = plain("layer", colors[c], 0.0f, 0.6f);
        m.baseColorFactor.a = 0.1f + 0.1f * float(c);
        m.alphaMode = AlphaMode::Blend;
        layerMaterial[c] = addMaterial(s, m);
    }
    for (int k = 0; k < 64; ++k) {
        Mesh layer = meshOf("layer", layerMaterial[k % 4]);
        const float inset = 0.01f * float(k), z = -4.6f + 0.03f * float(k);
        rect(layer, {-2.0f + inset, 0.3f + inset, z}, {4.0f - 2 * inset, 0, 0},
             {0, 2.6f - 2 * inset, 0}, {0, 0, 1});
        s.meshes.push_back(layer);
    }
    s.lights.push_back(point({-1.5f, 2.5f, 0.5f}, 12.0f, 7.0f, vec3(1.0f, 0.9f, 0.8f)));
    s.lights.push_back(point({2.0f, 1.0f, 1.0f}, 8.0f, 6.0f, vec3(0.6f, 0.8f, 1.0f)));
    s.lights.push_back(sun(vec3(0.3f, -0.6f, -1.0f), 1.0f));
    finish(s);
    return s;
}

Scene zeroRangeLights() {
    Scene s = stage("stress:lights-range-0");
    // One ordinary light first; then the inert ones (StressCase::inertLights counts them, at
    // the end of the list so the ordinary light keeps its index): range 0 and subnormal
    // ranges, point and spot, in mid-air, in the floor and wall planes, on the box, at the eye.
    s.lights.push_back(point({0.5f, 1.5f, 1.0f}, 20.0f, 8.0f));
    const float subnormal = 1e-40f, tiniest = std::numeric_limits<float>::denorm_min();
    const vec3 places[6] = {{-1, 1, 0},     {1.25f, 0, 0.5f}, {0.75f, 2, -5},
                            {-2, 1, -1.5f}, {2, 0.5f, -2},    s.camera.position};
    const float ranges[3] = {0.0f, subnormal, tiniest};
    for (int i = 0; i < 6; ++i)
        for (int r = 0; r < 3; ++r) {
            const vec3 p = places[i];
            if ((i + r) % 2 == 0)
                s.lights.push_back(point(p, 1.0e6f, ranges[r]));
            else
                s.lights.push_back(spot(p, {0, -1, -0.2f}, 1.0e6f, ranges[r], 0.2f, 0.6f));
        }
    finish(s);
    return s;
}

Scene cameraInLights() {
    Scene s = stage("stress:camera-in-light");
    // The eye 1.5 m above the floor looking at the wall: the lower third of the view is floor
    // within 3-4 m, which lights around the eye reach.
    s.camera.position = {0, 1.5f, 2};
    s.camera.target = {0, 1, -5};
    const vec3 eye = s.camera.position, forward = glm::normalize(s.camera.target - eye);
    // Each sphere holds the eye and lights part of the view, not all of it: a light 0.5 m
    // behind the eye, one centred on the near plane, one 1 m ahead and to the right (its
    // sphere crosses the near plane), one whose sphere passes 1 mm behind the eye, one that
    // reaches nothing visible, and a spot at the eye along the view (the eye at its apex).
    s.lights.push_back(point(eye - 0.5f * forward, 4.0f, 4.0f, vec3(1.0f, 0.8f, 0.6f)));
    s.lights.push_back(point(eye + s.camera.znear * forward, 3.0f, 3.6f, vec3(0.6f, 1.0f, 0.7f)));
    s.lights.push_back(point(eye + forward + vec3(0.5f, 0, 0), 3.0f, 3.0f, vec3(0.7f, 0.7f, 1.0f)));
    s.lights.push_back(point(eye + 2.0f * forward, 5.0f, 2.001f, vec3(1.0f, 0.5f, 0.5f)));
    s.lights.push_back(point(eye + vec3(0.3f, -0.2f, 0.1f), 50.0f, 0.4f));
    s.lights.push_back(spot(eye, forward, 60.0f, 9.0f, 0.15f, 0.3f, vec3(1.0f, 1.0f, 0.8f)));
    finish(s);
    return s;
}

Scene zeroConeSpots() {
    Scene s = stage("stress:spot-zero-cone");
    s.lights.push_back(point({0.5f, 1.5f, 1.0f}, 20.0f, 8.0f));
    // Zero cones whose axes run through pixel centres (of the case's 96 x 64), so the point
    // shaded there lies on the axis within rounding: the cosine to the axis is 1 or, after
    // rounding, a little above it (about one on-axis point in eight in fp32), where a zero
    // cone (scale 1e4, offset -1e4) would light with up to 4e-6 of the light. It must light
    // nothing, not even there. From the eye through an 8 x 8 grid of pixels (floor, wall,
    // box), from 2 m down the rays of the grid's middle row, straight down onto the floor,
    // and outer 0 below inner 0.3.
    const vec3 eye = s.camera.position;
    for (uint32_t j = 0; j < 8; ++j)
        for (uint32_t i = 0; i < 8; ++i) {
            const vec3 ray = pixelRay(s.camera, 96, 64, 5 + 12 * i, 3 + 8 * j);
            s.lights.push_back(spot(eye, ray, 1.0e3f, 20.0f, 0.0f, 0.0f));
            if (j == 4) s.lights.push_back(spot(eye + 2.0f * ray, ray, 1.0e3f, 20.0f, 0.0f, 0.0f));
        }
    s.lights.push_back(spot({-2, 3, 0}, {0, -1, 0}, 1.0e3f, 6.0f, 0.0f, 0.0f));
    s.lights.push_back(spot(eye, pixelRay(s.camera, 96, 64, 20, 50), 1.0e3f, 20.0f, 0.3f, 0.0f));
    finish(s);
    return s;
}

Scene hardSpots() {
    Scene s = stage("stress:spot-hard-edge");
    s.lights.push_back(point({1.5f, 2.0f, 1.5f}, 10.0f, 8.0f));
    // inner = outer > 0: the cone factor steps from 0 to 1 over 1e-4 of the cosine (the GPU's
    // clamp), far thinner than a pixel. Straight down, its circle across the floor and the
    // box; slanted, an ellipse across the floor running up the wall; a narrow one grazing the
    // wall from the side.
    s.lights.push_back(spot({-1.5f, 3.0f, -0.5f}, {0, -1, 0}, 60.0f, 8.0f, 0.45f, 0.45f));
    s.lights.push_back(spot({2.0f, 2.5f, 2.0f}, {-0.3f, -0.5f, -1.0f}, 80.0f, 12.0f, 0.3f, 0.3f,
                            {1.0f, 0.8f, 0.6f}));
    s.lights.push_back(spot({4.5f, 2.0f, -4.0f}, {-1.0f, -0.1f, -0.4f}, 40.0f, 10.0f, 0.2f, 0.2f,
                            {0.6f, 0.8f, 1.0f}));
    finish(s);
    return s;
}

} // namespace tp::stress
