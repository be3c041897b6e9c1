// The scene's meshlets on the GPU (core/scene/meshlets.h builds them, SceneGpu uploads them:
// ledger "scene", meshlets) and the two culling tests, written once for the GLSL of the cull
// pass (passes/meshlet_cull.comp) and the C++ of its tests. docs/geometry.md.
#ifndef TP_MESHLETS_H
#define TP_MESHLETS_H
#include "include/glsl_cpp.h"

// A cone test passes (the cluster is culled) only with this much to spare on the cosine: the
// rasterizer decides a triangle's facing from its snapped screen-space area, so a triangle
// within a hair of edge-on may count as front-facing there while the exact geometry calls it
// back-facing; and meshoptimizer's "no cone" cutoff of 1 must never cull.
#define TP_MESHLET_CONE_MARGIN 1e-3f
// The relative error of a world-space position after the camera-relative subtraction (a few
// fp32 ulps of the larger magnitude): spheres grow and cones shrink by it (scenes far from
// the origin, docs/shading.md "Camera-relative shading").
#define TP_MESHLET_POSITION_EPS 4.8e-7f
// scene.vert's flat output of a culled meshlet's first triangle (gl_InstanceIndex: the cull
// pass's firstInstance, TP_MC_FLAG_FIRST_TRIANGLE), after its locations 0..5; the visibility
// pass's fragment shader reads it (scene_meshlet_vert, scene_position_meshlet_vert).
#define TP_LOCATION_MESHLET_TRIANGLE 6

#ifndef TP_GLSL
namespace tp::gpu {
#endif

TP_STRUCT(MeshletGpu) {
    vec3 center;      // bounding sphere, world space
    float radius;
    vec3 coneApex;    // normal cone (meshopt_computeMeshletBounds), world space
    float coneCutoff; // back-facing from e when dot(normalize(apex - e), axis) >= cutoff
    vec3 coneAxis;
    uint triangleCount;
    uint firstIndex;   // into the meshlet index buffer (mesh-local vertex indices)
    uint pad0;
    uint pad1;
    uint pad2;
};

// Outside one frustum plane (xyz the inward normal, not normalized; w the offset) of the
// camera-relative clip space: the sphere (camera-relative centre) lies wholly behind it.
TP_INLINE bool meshletOutsidePlane(vec4 plane, vec3 center, float radius) {
    return dot(vec3(plane.x, plane.y, plane.z), center) + plane.w <
           -radius * length(vec3(plane.x, plane.y, plane.z));
}

// Every triangle of the cluster faces away from the eye (camera-relative apex: the eye at the
// origin). `slack`: the absolute error of the apex's position. A cutoff of 1 or more, a
// degenerate cone or an eye at the apex never cull.
TP_INLINE bool meshletConeCulls(vec3 apexRelative, vec3 axis, float cutoff, float slack) {
    const float len = length(apexRelative);
    return dot(apexRelative, axis) - slack > (cutoff + TP_MESHLET_CONE_MARGIN) * (len + slack);
}

#ifndef TP_GLSL
static_assert(sizeof(MeshletGpu) == 64);
static_assert(offsetof(MeshletGpu, coneApex) == 16);
static_assert(offsetof(MeshletGpu, coneAxis) == 32);
static_assert(offsetof(MeshletGpu, triangleCount) == 44);
static_assert(offsetof(MeshletGpu, firstIndex) == 48);
} // namespace tp::gpu
#endif
#endif
