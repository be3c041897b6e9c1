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
// The occlusion test's margins (--cull-geometry full; docs/geometry.md, "What is conservative").
// The relative error of rotating a camera-relative position into view space (a few fp32 ulps
// of its length): the sphere grows by it.
#define TP_MESHLET_ROTATION_EPS 1e-6f
// The sphere's nearest depth grows by this much, relatively: the rounding of scene.vert's
// clip position and of the rasterizer's depth interpolation (a few ulps each) stays far below.
#define TP_MESHLET_OCCLUSION_DEPTH_EPS 1e-5f
// The screen rectangle grows by this many pixels a side: the rounding of the projection.
#define TP_MESHLET_OCCLUSION_PIXELS 1.0f

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

// The occlusion test's two measures of a sphere (view-space centre: FrameUniforms.view applied
// to the camera-relative centre; looking down -z), under the symmetric reverse-Z perspective
// `proj` that camera.cpp builds (only proj[0][0], [1][1], [2][2] and [3][2] are non-zero).

// The largest depth (reverse-Z: the nearest) any point of the sphere can have, with
// TP_MESHLET_OCCLUSION_DEPTH_EPS to spare; -1 when the sphere reaches the near plane `znear`
// (or is not a number): such a sphere is never occluded.
TP_INLINE float sphereNearestDepth(vec3 viewCentre, float radius, mat4 proj, float znear) {
    const float nearest = -viewCentre.z - radius; // its nearest point's distance along the axis
    if (!(nearest > znear)) return -1.0f;
    // depth(z) = (proj[2][2] z + proj[3][2]) / -z, at z = -nearest; it falls with the distance.
    return (proj[3][2] / nearest - proj[2][2]) * (1.0f + TP_MESHLET_OCCLUSION_DEPTH_EPS);
}

// The pixels of a `size` frame that a sphere wholly in front of the near plane can cover:
// (x0, y0, x1, y1), continuous pixel coordinates (y down, as the viewport's negative height
// gives), TP_MESHLET_OCCLUSION_PIXELS to spare, not clipped to the frame. It is the projection
// of the view-space box around the sphere: every x/z and y/z of the box lies between the
// ratios at its corners, since its nearest face is in front of the eye.
TP_INLINE vec4 sphereScreenRect(vec3 viewCentre, float radius, mat4 proj, vec2 size) {
    const float zNear = -viewCentre.z - radius, zFar = -viewCentre.z + radius;
    const float xLo = min((viewCentre.x - radius) / zNear, (viewCentre.x - radius) / zFar);
    const float xHi = max((viewCentre.x + radius) / zNear, (viewCentre.x + radius) / zFar);
    const float yLo = min((viewCentre.y - radius) / zNear, (viewCentre.y - radius) / zFar);
    const float yHi = max((viewCentre.y + radius) / zNear, (viewCentre.y + radius) / zFar);
    // x_ndc = proj[0][0] x / -z, pixel (x_ndc + 1) w / 2; y_ndc = proj[1][1] y / -z, pixel
    // row (1 - y_ndc) h / 2.
    const float m = TP_MESHLET_OCCLUSION_PIXELS;
    return vec4((proj[0][0] * xLo + 1.0f) * 0.5f * size.x - m,
                (1.0f - proj[1][1] * yHi) * 0.5f * size.y - m,
                (proj[0][0] * xHi + 1.0f) * 0.5f * size.x + m,
                (1.0f - proj[1][1] * yLo) * 0.5f * size.y + m);
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
