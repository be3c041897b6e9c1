// The reference's exact visibility (TP_SHADOW_RAYS, include/shadow_light.glsl): a shadow ray
// from the surface to the light against the scene's opaque and masked triangles, through the
// BVH the reference built on the CPU (include/shadow_bvh.h, core/reference/shadow_bvh.h) in its
// own set (TP_SET_PASS). GLSL only; include after scene_bindings.glsl.
#ifndef TP_SHADOW_RAYS_GLSL
#define TP_SHADOW_RAYS_GLSL
#include "include/shadow_bvh.h"

layout(std430, set = TP_SET_PASS, binding = TP_BINDING_SHADOW_BVH_NODES) readonly buffer ShadowBvhNodeBlock {
    ShadowBvhNode shadowNodes[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BINDING_SHADOW_BVH_TRIANGLES) readonly buffer ShadowTriangleBlock {
    ShadowTriangle shadowTriangles[];
};

// Loop iterations this invocation's rays have taken (TP_SHADOW_RAY_STEP_BUDGET).
uint gShadowSteps = 0u;

// The base colour texture's alpha. The index differs between lanes (their rays hit different
// materials) and lavapipe has no shaderSampledImageArrayNonUniformIndexing, so the array is
// walked with a uniform counter (as the visibility buffer's resolve does); level 0, since a
// ray has no footprint to pick a level from.
float shadowTextureAlpha(int index, vec2 uv) {
    float a = 1.0;
    for (int i = 0; i < kTextureCount; ++i)
        if (i == index) a = textureLod(textures[i], uv, 0.0).a;
    gShadowSteps += uint(kTextureCount);
    return a;
}

// Whether the triangle blocks light at barycentrics (u, v): always unless masked; a masked one
// where its alpha (factor x vertex colour x texture, as the material's) reaches the cutoff,
// which is where the rasterized surface is kept (reference.frag discards below it).
bool shadowTriangleBlocks(ShadowTriangle tri, float u, float v) {
    if (tri.material == TP_SHADOW_OPAQUE) return true;
    MaterialGpu m = materials[tri.material];
    Vertex a = vertices[tri.v0], b = vertices[tri.v1], c = vertices[tri.v2];
    float w = 1.0 - u - v;
    vec2 uv = w * vec2(a.positionU.w, a.normalV.w) + u * vec2(b.positionU.w, b.normalV.w) +
              v * vec2(c.positionU.w, c.normalV.w);
    float alpha = m.baseColorFactor.a * (w * a.color.a + u * b.color.a + v * c.color.a);
    if (m.baseColorTexture >= 0) alpha *= shadowTextureAlpha(m.baseColorTexture, uv);
    return alpha >= m.alphaCutoff;
}

// A hit strictly between the origin (t = 0) and the light (t = 1: d is the whole segment);
// (u, v) of the hit in h.yz.
bool shadowTriangleHit(ShadowTriangle tri, vec3 o, vec3 d, out vec3 h) {
    h = rayTriangle(o, d, vertices[tri.v0].positionU.xyz, vertices[tri.v1].positionU.xyz,
                    vertices[tri.v2].positionU.xyz);
    return h.x > 0.0 && h.x < 1.0;
}
bool shadowOpaqueHit(uint index, vec3 o, vec3 d) {
    vec3 h;
    return shadowTriangleHit(shadowTriangles[index], o, d, h);
}

// Unrolled, not a loop: lavapipe counts every loop iteration against its limit. Opaque leaves
// only (a masked leaf is pushed and tested alone).
bool shadowLeafBlocks(uint first, uint info, vec3 o, vec3 d) {
    uint n = (info & TP_SHADOW_BVH_MASKED) != 0u ? 0u : info & TP_SHADOW_BVH_COUNT;
    if (n > 0u && shadowOpaqueHit(first, o, d)) return true;
    if (n > 1u && shadowOpaqueHit(first + 1u, o, d)) return true;
    if (n > 2u && shadowOpaqueHit(first + 2u, o, d)) return true;
    return n > 3u && shadowOpaqueHit(first + 3u, o, d);
}

// What an inner node's child adds to the stack: an inner node, a masked leaf (its triangle with
// TP_SHADOW_BVH_LEAF), or nothing (missed, or an opaque leaf, tested at once).
bool shadowPushes(uint info) { return info == 0u || (info & TP_SHADOW_BVH_MASKED) != 0u; }
uint shadowEntry(uint index, uint info) { return info == 0u ? index : TP_SHADOW_BVH_LEAF | index; }

// The iterations left to this ray: its own bound, within what the invocation has left after
// the light loop's (two lights an iteration, reference.frag) and the earlier rays' iterations.
uint shadowStepsLeft() {
    uint used = gShadowSteps + (frame.viewport.z + 1u) / 2u;
    return used >= TP_SHADOW_RAY_STEP_BUDGET ? 0u : min(TP_SHADOW_RAY_MAX_STEPS, TP_SHADOW_RAY_STEP_BUDGET - used);
}

// 0: a triangle blocks the segment from the surface to the light; 1: none does (or the ray
// was cut short by the iteration bounds: counted as lit, docs/shadows.md). position and
// light.position are camera-relative (shared.h); the BVH is in world space.
// lavapipe runs every branch of a loop body on every iteration (under a mask), so the node loop
// holds only box and opaque-triangle tests: it stops at a masked triangle, which the outer loop
// alpha-tests (texture fetches) before the node loop goes on where it stopped.
float shadowRayVisibility(LightGpu light, vec3 position, vec3 normal) {
    vec3 eye = frame.eyeWorld.xyz;
    vec3 o = shadowRayOrigin(position, eye, normal, light.position - position);
    vec3 d = (light.position + eye) - o;
    vec3 inv = shadowRayInvDir(d);
    uint stack[TP_SHADOW_BVH_STACK];
    uint sp = 1u, left = shadowStepsLeft(), used = 0u;
    stack[0] = 0u;
    bool blocked = false;
    while (used < left && sp > 0u && !blocked) {
        ++used; // this loop's own iteration
        uint masked = TP_SHADOW_OPAQUE;
        for (; used < left && sp > 0u; ) {
            ++used;
            uint entry = stack[--sp];
            if ((entry & TP_SHADOW_BVH_LEAF) != 0u) {
                masked = entry & ~TP_SHADOW_BVH_LEAF;
                break;
            }
            ShadowBvhNode n = shadowNodes[entry];
            bool hitA = rayBoxEntry(o, inv, 1.0, n.aMin, n.aMax) <= 1.0;
            bool hitB = rayBoxEntry(o, inv, 1.0, n.bMin, n.bMax) <= 1.0;
            if ((hitA && shadowLeafBlocks(n.a, n.aInfo, o, d)) ||
                (hitB && shadowLeafBlocks(n.b, n.bInfo, o, d))) {
                blocked = true;
                break;
            }
            if (hitA && shadowPushes(n.aInfo)) stack[sp++] = shadowEntry(n.a, n.aInfo);
            if (hitB && shadowPushes(n.bInfo)) stack[sp++] = shadowEntry(n.b, n.bInfo);
        }
        if (masked != TP_SHADOW_OPAQUE) {
            ShadowTriangle tri = shadowTriangles[masked];
            vec3 h;
            blocked = shadowTriangleHit(tri, o, d, h) && shadowTriangleBlocks(tri, h.y, h.z);
        }
    }
    gShadowSteps += used;
    return blocked ? 0.0 : 1.0;
}
#endif
