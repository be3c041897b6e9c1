// Meshlets (core/scene/meshlets.h) and the cull tests the GPU runs (include/meshlets.h):
// every triangle of a mesh in exactly one meshlet with its winding (and mapped back to itself
// by sourceTriangles), the limits held, each
// bounding sphere holding its vertices, and the normal-cone test conservative: whenever it
// culls, every triangle of the cluster faces away from the eye.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <random>

#include "core/camera/camera.h"
#include "core/scene/gltf_loader.h"
#include "core/scene/meshlets.h"
#include "core/scene/procedural.h"
#include "include/meshlets.h"
#include "passes/depth_pyramid.h"
#include "temp_path.h"
#include "transformed_scenes.h"

namespace tp {
namespace {

using Triangle = std::array<uint32_t, 3>;

// A triangle's corners rotated so the smallest index comes first: the same triangle with the
// same winding compares equal however the builder rotated it (it does not, but the winding
// is what must hold).
Triangle canonical(uint32_t a, uint32_t b, uint32_t c) {
    if (b < a && b < c) return {b, c, a};
    if (c < a && c < b) return {c, a, b};
    return {a, b, c};
}

// sourceTriangles: a permutation of the mesh's triangles, each meshlet triangle mapped to one
// with the same corners in the same order (the visibility buffer's ids name that one).
void expectSourceTriangles(const Mesh& mesh, const MeshMeshlets& m, const std::string& what) {
    const size_t triangles = m.indices.size() / 3;
    ASSERT_EQ(m.sourceTriangles.size(), triangles) << what;
    std::vector<bool> seen(triangles, false);
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t src = m.sourceTriangles[t];
        ASSERT_LT(src, triangles) << what;
        EXPECT_FALSE(seen[src]) << what << ": triangle " << src << " named twice";
        seen[src] = true;
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(m.indices[t * 3 + k], mesh.indices[src * 3 + k])
                << what << ": meshlet triangle " << t << " is not its source " << src;
    }
}

void expectMeshletsCoverMesh(const Mesh& mesh, const std::string& what) {
    const MeshMeshlets m = buildMeshlets(mesh);
    std::vector<Triangle> want, got;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        want.push_back(canonical(mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]));
    uint32_t next = 0;
    for (const Meshlet& ml : m.meshlets) {
        EXPECT_EQ(ml.firstIndex, next) << what << ": meshlets follow each other";
        EXPECT_GE(ml.triangleCount, 1u) << what;
        EXPECT_LE(ml.triangleCount, kMeshletMaxTriangles) << what;
        EXPECT_LE(ml.vertexCount, kMeshletMaxVertices) << what;
        std::vector<uint32_t> distinct(m.indices.begin() + ml.firstIndex,
                                       m.indices.begin() + ml.firstIndex + ml.triangleCount * 3);
        std::sort(distinct.begin(), distinct.end());
        distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
        EXPECT_LE(distinct.size(), size_t(kMeshletMaxVertices)) << what;
        for (uint32_t t = 0; t < ml.triangleCount; ++t) {
            const uint32_t* i = &m.indices[ml.firstIndex + t * 3];
            got.push_back(canonical(i[0], i[1], i[2]));
            // The bounding sphere holds the triangle's corners (with fp32 rounding).
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p = mesh.positions.at(i[k]);
                const float slack = 1e-5f * (ml.radius + glm::length(ml.center) + 1.0f);
                EXPECT_LE(glm::length(p - ml.center), ml.radius + slack)
                    << what << ": vertex " << i[k] << " outside its meshlet's sphere";
            }
        }
        next += ml.triangleCount * 3;
    }
    EXPECT_EQ(next, m.indices.size()) << what;
    expectSourceTriangles(mesh, m, what);
    std::sort(want.begin(), want.end());
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want) << what << ": every triangle once, with its winding";
}

TEST(Meshlets, CoverEveryTriangleOnceOnTheCourtyard) {
    Result<Scene> s = makeBuiltinScene("courtyard-small");
    ASSERT_TRUE(s.ok()) << s.error();
    size_t meshlets = 0;
    for (const Mesh& mesh : s->meshes) {
        expectMeshletsCoverMesh(mesh, mesh.name);
        meshlets += buildMeshlets(mesh).meshlets.size();
    }
    EXPECT_GE(meshlets, s->triangleCount() / kMeshletMaxTriangles);
}

// Mirrored nodes: the loader flips their winding, the meshlets keep it.
TEST(Meshlets, CoverEveryTriangleOnceUnderMirroredNodes) {
    const auto dir = testTempPath("meshlets_transformed");
    Result<Scene> s = loadGltf(test::writeTransformedNodesScene(dir, 3).string());
    ASSERT_TRUE(s.ok()) << s.error();
    for (const Mesh& mesh : s->meshes)
        expectMeshletsCoverMesh(mesh, mesh.name);
}

TEST(Meshlets, EmptyAndDegenerateMeshes) {
    Mesh empty;
    EXPECT_TRUE(buildMeshlets(empty).meshlets.empty());
    Mesh zeroArea; // three collinear triangles and one repeated corner: kept, covered once
    zeroArea.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    zeroArea.indices = {0, 1, 2, 0, 0, 3, 0, 1, 3};
    expectMeshletsCoverMesh(zeroArea, "zero-area");
    Mesh twice; // the same triangle three times: each copy named once (sourceTriangles)
    twice.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    twice.indices = {0, 1, 2, 1, 3, 2, 0, 1, 2, 0, 1, 2};
    expectMeshletsCoverMesh(twice, "duplicated triangles");
}

// A UV sphere of radius 1 at the origin, counter-clockwise seen from outside.
Mesh sphereMesh(uint32_t rings, uint32_t segments) {
    Mesh m;
    for (uint32_t r = 0; r <= rings; ++r)
        for (uint32_t s = 0; s <= segments; ++s) {
            const float theta = 3.14159265f * float(r) / float(rings);
            const float phi = 6.2831853f * float(s) / float(segments);
            m.positions.push_back({std::sin(theta) * std::cos(phi), std::cos(theta),
                                   -std::sin(theta) * std::sin(phi)});
        }
    for (uint32_t r = 0; r < rings; ++r)
        for (uint32_t s = 0; s < segments; ++s) {
            const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    return m;
}

bool culls(const Meshlet& ml, glm::vec3 eye) {
    return gpu::meshletConeCulls(ml.coneApex - eye, ml.coneAxis, ml.coneCutoff, 0.0f);
}

// Strictly back-facing from `eye` (the rasterizer culls it with VK_CULL_MODE_BACK_BIT and
// counter-clockwise front faces): the eye is behind the triangle's plane. A zero-area
// triangle (the sphere's poles) has no plane and no fragment: it counts as back-facing.
bool backFacing(const Mesh& m, const uint32_t* i, glm::vec3 eye) {
    const glm::dvec3 a(m.positions[i[0]]), b(m.positions[i[1]]), c(m.positions[i[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (n == glm::dvec3(0.0)) return true;
    return glm::dot(n, glm::dvec3(eye) - a) < 0.0;
}

TEST(Meshlets, ConeTestIsConservativeOnASphere) {
    const Mesh sphere = sphereMesh(24, 48);
    const MeshMeshlets m = buildMeshlets(sphere);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-6.0f, 6.0f);
    uint64_t culled = 0, tested = 0;
    for (int e = 0; e < 400; ++e) {
        const glm::vec3 eye(u(rng), u(rng), u(rng));
        if (glm::length(eye) < 1.05f) continue; // inside: sees the inside, all back faces
        for (const Meshlet& ml : m.meshlets) {
            ++tested;
            if (!culls(ml, eye)) continue;
            ++culled;
            for (uint32_t t = 0; t < ml.triangleCount; ++t)
                ASSERT_TRUE(backFacing(sphere, &m.indices[ml.firstIndex + t * 3], eye))
                    << "a culled meshlet has a front-facing triangle: eye " << eye.x << "," << eye.y
                    << "," << eye.z << ", triangle " << t;
        }
    }
    // From outside the sphere about half its triangles face away; a cluster goes only when all
    // of its triangles do, with the margin: 27 % of the tests culled when written.
    EXPECT_GT(double(culled), 0.2 * double(tested));
}

TEST(Meshlets, ConeHandCases) {
    // A flat 4x4 grid in z = 0 facing +z: one meshlet, its cone the +z axis.
    Mesh quad;
    for (int y = 0; y <= 4; ++y)
        for (int x = 0; x <= 4; ++x)
            quad.positions.push_back({float(x), float(y), 0.0f});
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 4; ++x) {
            const uint32_t a = y * 5 + x;
            quad.indices.insert(quad.indices.end(), {a, a + 1, a + 5, a + 1, a + 6, a + 5});
        }
    const MeshMeshlets m = buildMeshlets(quad);
    ASSERT_EQ(m.meshlets.size(), 1u);
    const Meshlet& ml = m.meshlets[0];
    EXPECT_NEAR(ml.coneAxis.z, 1.0f, 1e-5f);
    EXPECT_FALSE(culls(ml, {2, 2, 5}));   // in front
    EXPECT_TRUE(culls(ml, {2, 2, -5}));   // behind
    EXPECT_TRUE(culls(ml, {50, 2, -1}));  // behind, far to the side
    EXPECT_FALSE(culls(ml, {50, 2, 0}));  // edge-on: the rasterizer may still draw it
    EXPECT_FALSE(culls(ml, {50, 2, 1}));  // grazing, in front
    EXPECT_FALSE(culls(ml, ml.coneApex)); // at the apex: no direction, no cull

    // A closed box faces every way: no useful cone (cutoff 1), culled from nowhere.
    Mesh box;
    box.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                     {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    box.indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                   2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
    const MeshMeshlets b = buildMeshlets(box);
    ASSERT_EQ(b.meshlets.size(), 1u);
    for (glm::vec3 eye : {glm::vec3(0.5f, 0.5f, 9), glm::vec3(0.5f, 0.5f, -9),
                          glm::vec3(9, 0.5f, 0.5f), glm::vec3(0.5f, 0.5f, 0.5f)})
        EXPECT_FALSE(culls(b.meshlets[0], eye));

    // The slack of a position far from the origin only ever keeps more.
    EXPECT_FALSE(
        gpu::meshletConeCulls(ml.coneApex - glm::vec3(2, 2, -5), ml.coneAxis, ml.coneCutoff, 1e3f));
}

TEST(Meshlets, FrustumPlaneTest) {
    const gpu::vec4 plane(0, 0, 2, -4); // z >= 2, normal not normalized
    EXPECT_TRUE(gpu::meshletOutsidePlane(plane, {0, 0, 0}, 1.9f));
    EXPECT_FALSE(gpu::meshletOutsidePlane(plane, {0, 0, 0}, 2.1f));
    EXPECT_FALSE(gpu::meshletOutsidePlane(plane, {5, 5, 3}, 0.0f));
}

} // namespace
} // namespace tp

namespace tp {
namespace {

// The occlusion test's footprint (include/meshlets.h): every point of a sphere in front of the
// near plane projects (in double, through the same projection) inside its pixel rectangle, at
// a depth no larger than its nearest depth; a sphere that reaches the near plane gets none.
TEST(MeshletOcclusion, FootprintHoldsEveryPointOfTheSphere) {
    const uint32_t w = 320, h = 180;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (float zfar : {0.0f, 200.0f}) {
        const glm::mat4 proj = reverseZPerspective(1.0f, float(w) / float(h), 0.05f, zfar);
        const glm::dmat4 projD(proj);
        uint64_t spheres = 0, nearCrossing = 0;
        for (int i = 0; i < 3000; ++i) {
            const glm::vec3 c(u(rng) * 20.0f, u(rng) * 12.0f, -(u(rng) + 1.0f) * 40.0f);
            const float r = (u(rng) + 1.05f) * (i % 3 == 0 ? 8.0f : 0.5f);
            const float depth = gpu::sphereNearestDepth(c, r, proj, 0.05f);
            if (depth < 0.0f) {
                EXPECT_LE(-c.z - r, 0.05f) << "a sphere in front of the near plane got no depth";
                ++nearCrossing;
                continue;
            }
            ++spheres;
            const glm::vec4 rect = gpu::sphereScreenRect(c, r, proj, glm::vec2(w, h));
            for (int k = 0; k < 200; ++k) {
                glm::dvec3 d(u(rng), u(rng), u(rng));
                if (glm::length(d) == 0.0) continue;
                const glm::dvec3 p = glm::dvec3(c) + double(r) * glm::normalize(d);
                const glm::dvec4 clip = projD * glm::dvec4(p, 1.0);
                const double x = (clip.x / clip.w + 1.0) * 0.5 * w;
                const double y = (1.0 - clip.y / clip.w) * 0.5 * h;
                ASSERT_GE(x, rect.x) << i;
                ASSERT_LE(x, rect.z) << i;
                ASSERT_GE(y, rect.y) << i;
                ASSERT_LE(y, rect.w) << i;
                ASSERT_LE(clip.z / clip.w, double(depth)) << i;
            }
        }
        EXPECT_GT(spheres, 1000u);
        EXPECT_GT(nearCrossing, 10u);
    }
}

// The pyramid's levels: each ceil(n / 2^(level+1)), down to exactly 1x1, packed one after another.
TEST(MeshletOcclusion, PyramidLevels) {
    for (auto [w, h] : std::vector<std::pair<uint32_t, uint32_t>>{
             {1, 1}, {2, 2}, {3, 5}, {64, 48}, {96, 54}, {1280, 720}, {1920, 1080}}) {
        const uint32_t levels = gpu::pyramidLevels(w, h);
        uint32_t offset = 0;
        for (uint32_t l = 0; l < levels; ++l) {
            const glm::uvec2 s = gpu::pyramidLevelSize(w, h, l);
            EXPECT_EQ(s.x, (w + (2u << l) - 1) / (2u << l)) << w << "x" << h << " level " << l;
            EXPECT_EQ(s.y, (h + (2u << l) - 1) / (2u << l)) << w << "x" << h << " level " << l;
            EXPECT_EQ(gpu::pyramidLevelOffset(w, h, l), offset);
            offset += s.x * s.y;
        }
        EXPECT_EQ(gpu::pyramidLevelSize(w, h, levels - 1), glm::uvec2(1, 1)) << w << "x" << h;
        if (levels > 1) {
            EXPECT_NE(gpu::pyramidLevelSize(w, h, levels - 2), glm::uvec2(1, 1));
        }
    }
    EXPECT_EQ(gpu::pyramidLevels(1920, 1080), 11u); // 960 x 540 down to 1 x 1
}

} // namespace
} // namespace tp
