// The reference's shadow rays (docs/shadows.md, "Exact visibility: the ray-traced reference"):
// a bounding volume hierarchy over the scene's opaque and masked triangles, built on the CPU
// (core/reference/shadow_bvh.h) and traversed by include/shadow_rays.glsl. Shared by C++ and
// GLSL (the intersection tests below run on both sides: the CPU test checks the very code the
// shader runs); include after shared.h.
//
// World space: a triangle's corners are the scene's vertices (set 0's vertex buffer, which
// holds world positions), so the BVH owns no positions, only its boxes and its triangles'
// vertex indices. A node holds its two children's boxes (one fetch tests both); a child is an
// inner node (info 0) or a leaf of consecutive triangles (info = TP_SHADOW_BVH_LEAF | count).
// The root (node 0) is always an inner node: child a holds the opaque triangles (leaves of up to
// TP_SHADOW_BVH_LEAF_MAX), child b the masked ones (leaves of one, TP_SHADOW_BVH_MASKED: each is
// alpha-tested on its own, outside the node loop); either may be an empty leaf (count 0).
#ifndef TP_SHADOW_BVH_H
#define TP_SHADOW_BVH_H
#include "include/shared.h"

#define TP_BINDING_SHADOW_BVH_NODES 0     // set TP_SET_PASS: buffer ShadowBvhNode[]
#define TP_BINDING_SHADOW_BVH_TRIANGLES 1 // set TP_SET_PASS: buffer ShadowTriangle[]
#define TP_SHADOW_BVH_LEAF 0x80000000u    // ShadowBvhNode info: a leaf (low bits: its count)
#define TP_SHADOW_BVH_MASKED 0x40000000u  // ... of one masked triangle
#define TP_SHADOW_BVH_COUNT 0x3FFFFFFFu   // the count bits of a leaf's info
#define TP_SHADOW_BVH_LEAF_MAX 4u         // triangles per leaf at most (tested unrolled)
#define TP_SHADOW_BVH_MAX_DEPTH 60u       // inner nodes on a path, at most (the builder's bound)
#define TP_SHADOW_BVH_STACK 64            // traversal stack: one entry per level and one more
#define TP_SHADOW_OPAQUE 0xFFFFFFFFu      // ShadowTriangle.material of a triangle never alpha-tested
// Iterations (nodes) one shadow ray may take, and all the rays of one invocation together:
// lavapipe ends an invocation after 65,535 loop iterations over all its loops (docs/shading.md),
// the light loop's included; a ray past either bound is cut short and counts as lit.
#define TP_SHADOW_RAY_MAX_STEPS 4096u
#define TP_SHADOW_RAY_STEP_BUDGET 60000u
// The ray leaves the surface this many fp32 ulps (of its world and camera-relative positions'
// largest coordinates) along the normal, toward the light; at least TP_SHADOW_RAY_OFFSET_MIN m.
#define TP_SHADOW_RAY_OFFSET_ULPS 64.0f
#define TP_SHADOW_RAY_OFFSET_MIN 1e-5f

#ifndef TP_GLSL
namespace tp::gpu {
using glm::abs;
using glm::cross;
#endif

TP_STRUCT(ShadowBvhNode) {
    vec3 aMin;
    uint a;     // inner: the child node's index; leaf: its first ShadowTriangle
    vec3 aMax;
    uint aInfo; // 0: inner; TP_SHADOW_BVH_LEAF | count: a leaf
    vec3 bMin;
    uint b;
    vec3 bMax;
    uint bInfo;
};

TP_STRUCT(ShadowTriangle) {
    uint v0; // indices into set 0's vertices (the global vertex numbering of SceneGpu)
    uint v1;
    uint v2;
    uint material; // MaterialGpu index of a masked triangle, else TP_SHADOW_OPAQUE
};

// The ray's entry into [lo, hi] within (0, tMax), or a value > tMax when it misses; invDir is
// 1 / direction with no zero component (shadowRayInvDir).
TP_INLINE float rayBoxEntry(vec3 origin, vec3 invDir, float tMax, vec3 lo, vec3 hi) {
    vec3 t0 = (lo - origin) * invDir;
    vec3 t1 = (hi - origin) * invDir;
    vec3 tn = min(t0, t1), tf = max(t0, t1);
    float enter = max(max(tn.x, tn.y), max(tn.z, 0.0f));
    float leave = min(min(tf.x, tf.y), min(tf.z, tMax));
    return enter <= leave ? enter : tMax + 1.0f;
}

// Components of magnitude below 1e-30 are moved to +-1e-30, so 1 / d stays finite and a slab
// the ray runs parallel to gives +-huge instead of NaN (0 * inf).
TP_INLINE vec3 shadowRayInvDir(vec3 d) {
    vec3 s = vec3(d.x < 0.0f ? -1.0f : 1.0f, d.y < 0.0f ? -1.0f : 1.0f, d.z < 0.0f ? -1.0f : 1.0f);
    return vec3(1.0f) / (s * max(abs(d), vec3(1e-30f)));
}

// Moeller-Trumbore: (t, u, v) of the ray's hit with the triangle, both faces; t <= 0 when the
// ray runs parallel to its plane or passes outside it (edges included: a ray through a shared
// edge hits both triangles rather than neither).
TP_INLINE vec3 rayTriangle(vec3 origin, vec3 dir, vec3 p0, vec3 p1, vec3 p2) {
    vec3 e1 = p1 - p0, e2 = p2 - p0;
    vec3 pv = cross(dir, e2);
    float det = dot(e1, pv);
    if (abs(det) < 1e-30f) return vec3(-1.0f, 0.0f, 0.0f);
    float inv = 1.0f / det;
    vec3 tv = origin - p0;
    float u = dot(tv, pv) * inv;
    vec3 qv = cross(tv, e1);
    float v = dot(dir, qv) * inv;
    if (u < 0.0f || v < 0.0f || u + v > 1.0f) return vec3(-1.0f, 0.0f, 0.0f);
    return vec3(dot(e2, qv) * inv, u, v);
}

// The shadow ray's origin in world space: the camera-relative surface point plus the eye (the
// shader's only world position), moved along its normal (turned toward the light) by an offset
// that scales with the fp32 spacing of both coordinates, since each rounding of relPos and of
// the sum is half an ulp of its magnitude (docs/shadows.md).
TP_INLINE vec3 shadowRayOrigin(vec3 relPos, vec3 eyeWorld, vec3 normal, vec3 toLight) {
    vec3 w = relPos + eyeWorld;
    vec3 a = abs(w), r = abs(relPos);
    float scale = max(max(a.x, a.y), a.z) + max(max(r.x, r.y), r.z);
    float offset = max(TP_SHADOW_RAY_OFFSET_MIN, scale * TP_SHADOW_RAY_OFFSET_ULPS * 1.1920929e-7f);
    vec3 n = dot(normal, toLight) < 0.0f ? -normal : normal;
    return w + n * offset;
}

#ifndef TP_GLSL
static_assert(sizeof(ShadowBvhNode) == 64);
static_assert(offsetof(ShadowBvhNode, aInfo) == 28);
static_assert(offsetof(ShadowBvhNode, bMin) == 32);
static_assert(offsetof(ShadowBvhNode, bInfo) == 60);
static_assert(sizeof(ShadowTriangle) == 16);
static_assert(TP_SHADOW_BVH_STACK >= TP_SHADOW_BVH_MAX_DEPTH + 1);
} // namespace tp::gpu
#endif
#endif
