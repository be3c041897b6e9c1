// The reference's exact visibility (shadow rays through its BVH, docs/shadows.md) against the
// analytic case of issue 26: a square occluder over a plane, a point light on its axis. The
// umbra of a point light is the whole shadow: a square of side s H / (H - h). The light is
// shadowed by --shadows all (settings.shadows).
#include <algorithm>
#include <cmath>

#include "core/reference/shadow_rays.h"
#include "core/renderer/renderer.h"
#include "gpu_test_util.h"

namespace tp::test {
namespace {

constexpr float kSide = 1.0f;          // occluder's side s
constexpr float kOccluderHeight = 1.0f; // h
constexpr float kLightHeight = 4.0f;    // H
constexpr float kCameraHeight = 10.0f;
constexpr float kHalfView = 4.0f;       // the view spans 8 m of the plane at y = 0
constexpr uint32_t kRes = 128;

// A 20 x 20 plane at y = 0 seen straight from above; with `occluder`, the s x s square at
// height h, single-sided and facing down: culled from the camera (which sees the whole plane)
// but in the shadow rays' BVH, which tests both faces.
Scene occluderScene(bool occluder) {
    Scene s;
    s.source = "test:occluder";
    Material white;
    white.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    white.metallicFactor = 0.0f;
    white.roughnessFactor = 1.0f;
    s.materials = {white};
    Mesh plane;
    addQuad(plane, {-10, 0, 10}, {20, 0, 0}, {0, 0, -20}); // CCW seen from +y
    s.meshes = {plane};
    if (occluder) {
        Mesh square;
        const float r = kSide * 0.5f;
        addQuad(square, {-r, kOccluderHeight, -r}, {kSide, 0, 0}, {0, 0, kSide}); // faces -y
        s.meshes.push_back(square);
    }
    Light l;
    l.position = {0, kLightHeight, 0};
    l.range = 30.0f;
    l.intensity = 40.0f;
    s.lights = {l};
    s.camera.position = {0, kCameraHeight, 0};
    s.camera.target = {0, 0, 0};
    s.camera.up = {0, 0, -1};
    s.camera.yfov = 2.0f * std::atan(kHalfView / kCameraHeight);
    s.camera.znear = 0.1f;
    s.ambient = glm::vec3(0.01f);
    s.computeBounds();
    return s;
}

glm::vec3 unprojectPixel(const gpu::FrameUniforms& f, uint32_t x, uint32_t y, float depth) {
    float w = float(f.viewport.x), h = float(f.viewport.y);
    glm::vec4 ndc((x + 0.5f) / w * 2.0f - 1.0f, 1.0f - (y + 0.5f) / h * 2.0f, depth, 1.0f);
    glm::vec4 p = f.invViewProj * ndc;
    return glm::vec3(p) / p.w;
}

struct Umbra {
    uint32_t pixels = 0;
    glm::vec2 min{1e30f}, max{-1e30f}; // x, z extent of the shadowed pixels' centres
};

// Pixels whose red radiance is below half of the same pixel without the occluder.
Umbra measureUmbra(const RunResult& shadowed, const RunResult& open, const gpu::FrameUniforms& f) {
    Umbra u;
    for (uint32_t y = 0; y < kRes; ++y)
        for (uint32_t x = 0; x < kRes; ++x) {
            if (shadowed.hdr.at(x, y)[0] >= 0.5f * open.hdr.at(x, y)[0]) continue;
            ++u.pixels;
            glm::vec3 p = unprojectPixel(f, x, y, shadowed.depth.r[y * kRes + x]);
            u.min = glm::min(u.min, glm::vec2(p.x, p.z));
            u.max = glm::max(u.max, glm::vec2(p.x, p.z));
        }
    return u;
}

} // namespace

TEST(ShadowRays, UmbraOfASquareOccluderHasTheAnalyticArea) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    Scene withOccluder = occluderScene(true), without = occluderScene(false);
    SceneGpu gpuWith(*ctx, withOccluder), gpuWithout(*ctx, without);
    // The open plane without shadows: self-shadowing (acne) of the plane would count too.
    RenderSettings settings;
    settings.width = settings.height = kRes;
    RunResult open = runOrFail(*ctx, gpuWithout, "reference", settings);
    settings.shadows.all = true;
    RunResult shadowed = runOrFail(*ctx, gpuWith, "reference", settings);
    ASSERT_TRUE(ref::anyLightShadowed(gpuWith));
    EXPECT_EQ(shadowed.stats.counter("shadow_bvh_triangles"), 4.0); // the plane and the square

    // Straight down at a plane parallel to the image: every pixel covers the same square.
    const float pixel = 2.0f * kHalfView / float(kRes);
    const float side = kSide * kLightHeight / (kLightHeight - kOccluderHeight) / pixel;
    const Umbra u = measureUmbra(shadowed, open, gpuWith.frame());
    // Bound: a pixel is misclassified only where the umbra's edge crosses it, and then by at
    // most its whole area: at most the pixels along the perimeter, 4 side + 4 (the corners).
    const float analytic = side * side, bound = 4.0f * side + 4.0f;
    EXPECT_NEAR(float(u.pixels), analytic, bound) << "umbra side " << side << " pixels";
    // Its extent: the outermost shadowed centres lie within a pixel inside the analytic edge.
    const float half = 0.5f * side * pixel;
    for (int a = 0; a < 2; ++a) {
        EXPECT_NEAR(u.min[a], -half, pixel) << "axis " << a;
        EXPECT_NEAR(u.max[a], half, pixel) << "axis " << a;
    }
    expectNoValidationMessages(*ctx);
    std::printf("umbra: %u pixels, analytic %.1f (bound %.1f), x %.3f..%.3f z %.3f..%.3f m "
                "(analytic +-%.3f)\n",
                u.pixels, analytic, bound, u.min.x, u.max.x, u.min.y, u.max.y, half);
}

} // namespace tp::test
