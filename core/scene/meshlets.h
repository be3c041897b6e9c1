#pragma once
// Meshlets: every mesh split into clusters of at most kMeshletMaxVertices vertices and
// kMeshletMaxTriangles triangles (meshoptimizer's meshopt_buildMeshlets), each with a bounding
// sphere and a normal cone (meshopt_computeMeshletBounds), for culling clusters on the GPU
// (core/passes/meshlet_cull.h, docs/geometry.md). API-free: SceneGpu uploads them.
//
// The clusters' triangles are the mesh's, each exactly once, with each triangle's corners in
// the mesh's order (a, b, c: the winding, mirrored nodes already flipped by the loader, is
// kept), expanded to mesh-local vertex indices: `indices` is an index buffer in meshlet order.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/scene/scene.h"

namespace tp {

// 64 vertices and 124 triangles: the sizes NVIDIA recommends for mesh shaders and niagara
// uses (124 = 128 - 4 keeps the primitive indices of a mesh shader in 128 x 3 bytes); the
// 0.18 builder wants a multiple of 4 triangles.
constexpr uint32_t kMeshletMaxVertices = 64;
constexpr uint32_t kMeshletMaxTriangles = 124;
// How much the builder favours a tight normal cone over a small cluster (meshoptimizer's
// suggested 0.25: the cone matters, as the clusters are cone-culled).
constexpr float kMeshletConeWeight = 0.25f;

struct Meshlet {
    uint32_t firstIndex = 0;    // into MeshMeshlets::indices (3 per triangle)
    uint32_t triangleCount = 0; // <= kMeshletMaxTriangles
    uint32_t vertexCount = 0;   // distinct vertices, <= kMeshletMaxVertices
    glm::vec3 center{0.0f};     // bounding sphere, world space
    float radius = 0.0f;
    // Normal cone: every triangle faces away from an eye e when
    // dot(normalize(apex - e), axis) >= cutoff (cutoff 1: no useful cone).
    glm::vec3 coneApex{0.0f};
    glm::vec3 coneAxis{0.0f};
    float coneCutoff = 1.0f;
};

struct MeshMeshlets {
    std::vector<Meshlet> meshlets;
    std::vector<uint32_t> indices; // mesh-local vertex indices, meshlet after meshlet
    // Per triangle of `indices` (meshlet order): the triangle of the mesh's own index list it
    // is (the same three corners, in order). The builder reorders triangles, and the visibility
    // buffer's ids name a draw's triangles in the mesh's order: a culled draw maps its
    // meshlet-order triangle back through this (docs/geometry.md).
    std::vector<uint32_t> sourceTriangles;
};

// The mesh's meshlets (none for a mesh without triangles).
MeshMeshlets buildMeshlets(const Mesh& mesh);

} // namespace tp
