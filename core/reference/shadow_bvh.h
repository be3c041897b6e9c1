#pragma once
// The reference's shadow-ray BVH (docs/shadows.md, "Exact visibility: the ray-traced
// reference"), built on the CPU over the scene's opaque and masked triangles and flattened
// into the std430 arrays of shaders/include/shadow_bvh.h. Blended triangles cast no shadow:
// the pipelines' shadow maps render opaque and masked draws only, and the reference agrees.
//
// Binned SAH (16 bins a axis, the three axes, centroid bounds), with leaves of at most
// TP_SHADOW_BVH_LEAF_MAX triangles, switching to median splits where a path could otherwise
// outgrow TP_SHADOW_BVH_MAX_DEPTH (the shader's fixed stack).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/scene/scene.h"
#include "include/shadow_bvh.h"

namespace tp::ref {

// Triangles in the vertex numbering SceneGpu uploads (every mesh's vertices, meshes in order):
// the shader reads the corners from set 0's vertex buffer.
struct ShadowBvhInput {
    std::vector<glm::vec3> positions; // world space, by global vertex index
    std::vector<gpu::ShadowTriangle> triangles;
};
ShadowBvhInput shadowBvhInput(const Scene& scene);

struct ShadowBvh {
    std::vector<gpu::ShadowBvhNode> nodes; // node 0 is the root
    std::vector<gpu::ShadowTriangle> triangles; // in leaf order
    uint32_t depth = 0;  // inner nodes on the longest path
    double buildMs = 0;  // wall-clock time of buildShadowBvh
};

// Any input, also none (a root with two empty leaves).
ShadowBvh buildShadowBvh(const std::vector<glm::vec3>& positions,
                         const std::vector<gpu::ShadowTriangle>& triangles);

// The shader's traversal on the CPU (masked triangles count as opaque: no textures here):
// whether a triangle blocks the segment from origin to target, strictly between them.
// `steps`, when given, receives the node visits (the shader's loop iterations).
bool shadowRayBlocked(const ShadowBvh& bvh, const std::vector<glm::vec3>& positions,
                      glm::vec3 origin, glm::vec3 target, uint32_t* steps = nullptr);

} // namespace tp::ref
