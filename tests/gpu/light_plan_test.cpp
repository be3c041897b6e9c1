// Multipass forward's per-light draw selection (multipass_forward/light_plan.*) on a scene
// whose meshes reach world space through mirrored, non-uniformly scaled, rotated and
// translated nodes, lit by spheres that barely touch a surface near a triangle's corner or
// edge: where a draw's box and its triangles part most, and where a light selection that is
// not conservative loses a light (lavapipe, validation on).
#include <cmath>
#include <set>

#include "core/camera/camera.h"
#include "core/scene/gltf_loader.h"
#include "gpu_test_util.h"
#include "multipass_forward/light_plan.h"
#include "temp_path.h"
#include "transformed_scenes.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 5.1.5).
glm::dvec3 closestOnTriangle(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

Scene loadTransformedScene(uint32_t seed) {
    // One folder per process: ctest -j runs this file's tests side by side.
    const fs::path dir = testTempPath("transformed_" + std::to_string(seed));
    Result<Scene> scene = loadGltf(writeTransformedNodesScene(dir, seed).string());
    EXPECT_TRUE(scene.ok()) << scene.error();
    return scene.ok() ? std::move(*scene) : Scene{};
}

// Every surface point a light reaches (inside its sphere, in front of the near plane, on
// screen) lies on a draw of that light's pass and inside its scissor: checked at the point of
// each triangle closest to the light, the one a barely touching sphere reaches first.
TEST(LightPlan, EveryLitSurfacePointIsInItsLightsPassUnderNodeTransforms) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    uint32_t reached = 0;
    for (uint32_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
        Scene scene = loadTransformedScene(seed);
        ASSERT_FALSE(scene.meshes.empty());
        scene.lights = lightsGrazingSurfaces(scene, 300, seed);
        // The framing camera, then cameras among the meshes (boxes around and behind the eye,
        // spheres crossing the near plane), at two aspect ratios and sizes.
        const uint32_t w = seed % 2 ? 160 : 96, h = seed % 2 ? 90 : 96;
        if (seed > 2) {
            const glm::vec3 c = scene.bounds.center(), e = scene.bounds.extent();
            scene.camera.position = c + e * glm::vec3(0.3f * float(seed % 3) - 0.3f, 0.1f, 0.25f);
            scene.camera.target = c - e * glm::vec3(0.1f * float(seed), 0.0f, 0.5f);
            scene.camera.yfov = 0.5f + 0.2f * float(seed);
        }
        SceneGpu gpuScene(*ctx, scene);
        gpuScene.setView(w, h, 1);
        const mp::LightPlan plan = mp::planLights(gpuScene);
        const std::vector<const DrawItem*> draws = gpuScene.drawList(DrawFilter::Opaque);
        ASSERT_EQ(draws.size(), scene.meshes.size()); // one draw per mesh, in order
        const glm::dmat4 viewProj = glm::dmat4(gpuScene.frame().viewProj);
        const double znear = scene.camera.znear;
        for (uint32_t i = 0; i < scene.lights.size(); ++i) {
            const Light& l = scene.lights[i];
            const mp::LightBatch* batch = nullptr;
            for (const mp::LightBatch& b : plan.batches)
                if (b.light == i) batch = &b;
            const std::set<const DrawItem*> selected =
                batch ? std::set<const DrawItem*>(batch->draws.begin(), batch->draws.end())
                      : std::set<const DrawItem*>{};
            for (size_t m = 0; m < scene.meshes.size(); ++m) {
                const Mesh& mesh = scene.meshes[m];
                for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
                    const glm::dvec3 p = closestOnTriangle(
                        glm::dvec3(l.position), glm::dvec3(mesh.positions[mesh.indices[t]]),
                        glm::dvec3(mesh.positions[mesh.indices[t + 1]]),
                        glm::dvec3(mesh.positions[mesh.indices[t + 2]]));
                    if (glm::length(p - glm::dvec3(l.position)) >= double(l.range)) continue;
                    const glm::dvec4 clip = viewProj * glm::dvec4(p, 1.0);
                    if (clip.w <= znear) continue;
                    const double px = (clip.x / clip.w * 0.5 + 0.5) * w,
                                 py = (0.5 - clip.y / clip.w * 0.5) * h;
                    if (px < 0 || py < 0 || px >= w || py >= h) continue;
                    ++reached;
                    const std::string where = "seed " + std::to_string(seed) + " light " +
                                              std::to_string(i) + " mesh " + std::to_string(m) +
                                              " at pixel (" + std::to_string(px) + ", " +
                                              std::to_string(py) + ")";
                    ASSERT_TRUE(selected.count(draws[m]))
                        << where << ": the light's pass does not draw the mesh";
                    EXPECT_TRUE(px >= batch->scissor.x0 && px <= batch->scissor.x1 &&
                                py >= batch->scissor.y0 && py <= batch->scissor.y1)
                        << where << ": outside the scissor";
                }
            }
        }
    }
    EXPECT_GT(reached, 500u); // the lights do reach visible surfaces
    expectNoValidationMessages(*ctx);
}

// The same scenes end to end: multipass forward sums the reference's terms in another order,
// so it agrees with the reference within the summation bound (a light missing from a mesh it
// touches is far outside it).
TEST(LightPlan, MultipassMatchesTheReferenceUnderNodeTransforms) {
    auto ctx = makeValidatedContext();
    ASSERT_TRUE(ctx);
    for (uint32_t seed : {1u, 2u}) {
        Scene scene = loadTransformedScene(seed);
        scene.lights = lightsGrazingSurfaces(scene, 48, seed + 100);
        SceneGpu gpuScene(*ctx, scene);
        RenderSettings s;
        s.width = 128;
        s.height = 72;
        RunResult ref = runOrFail(*ctx, gpuScene, "reference", s);
        RunResult mp = runOrFail(*ctx, gpuScene, "multipass_forward", s);
        expectAgreeWithinSummationBound(mp.hdr, ref.hdr, uint32_t(scene.lights.size()), 1,
                                        "multipass vs reference, transformed nodes seed " +
                                            std::to_string(seed));
    }
    expectNoValidationMessages(*ctx);
}

} // namespace
} // namespace tp::test
