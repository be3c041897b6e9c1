// The light-volume meshes of `--deferred-lighting volumes` (shaders/deferred/deferred_shared.h):
// a volume must contain the light's whole region, or pixels inside it lose the light, and
// its triangles must face outward, or culling front faces would drop the wrong half.
#include <gtest/gtest.h>

#include "deferred/volume_lighting.h"

namespace tp::gpu {
namespace {

// Signed distance from the origin-side: every non-degenerate triangle's plane must have
// `inside` on its inner side at distance >= `clearance`, with the normal (CCW) outward.
template <typename Vertex>
void expectConvexOutwardAround(Vertex vertex, uint32_t count, glm::vec3 inside, float clearance) {
    for (uint32_t k = 0; k < count; k += 3) {
        glm::vec3 a = vertex(k), b = vertex(k + 1), c = vertex(k + 2);
        glm::vec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-6f) continue;
        float d = glm::dot(glm::normalize(n), a - inside);
        EXPECT_GE(d, clearance) << "triangle " << k / 3;
    }
}

TEST(DeferredVolumeMesh, ScaledSphereCircumscribesTheUnitSphereOutwardFacing) {
    float scale = circumscribedSphereScale();
    EXPECT_GT(scale, 1.0f);
    EXPECT_LT(scale, 1.1f); // 8 x 16 quads: 1 / (cos(pi/16) cos(pi/16)) ~ 1.04
    expectConvexOutwardAround([&](uint32_t k) { return volumeSphereVertex(k) * scale; },
                              TP_DEF_SPHERE_VERTICES, glm::vec3(0.0f), 1.0f);
}

// The unit cone (apex 0, cap z = 1, slope 1) holds every point at angle <= 45 degrees
// from +z with z <= 1: its planes keep the round cone's points at distance >= 0.
TEST(DeferredVolumeMesh, ConeContainsTheRoundConeOutwardFacing) {
    for (uint32_t k = 0; k < TP_DEF_CONE_VERTICES; k += 3) {
        glm::vec3 a = volumeConeVertex(k), b = volumeConeVertex(k + 1), c = volumeConeVertex(k + 2);
        glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        for (int i = 0; i < 720; ++i) {
            float angle = float(i) * 3.14159265f / 360.0f;
            for (float z : {1e-3f, 0.5f, 1.0f}) {
                glm::vec3 p(z * std::cos(angle), z * std::sin(angle), z); // on the round cone's rim
                EXPECT_LE(glm::dot(n, p - a), 1e-5f) << "triangle " << k / 3;
            }
        }
    }
    expectConvexOutwardAround([](uint32_t k) { return volumeConeVertex(k); }, TP_DEF_CONE_VERTICES,
                              glm::vec3(0.0f, 0.0f, 0.5f), 0.0f);
}

} // namespace
} // namespace tp::gpu
