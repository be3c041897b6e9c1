// multipass forward's light-draws pass (multipass_forward/light_draw_pass.h, light_draws.comp): its
// bindings in set TP_SET_PASS, the per-view tables the CPU writes and the layout of the indirect
// draws it writes. docs/multipass_forward.md, "Light lists on the GPU".
#ifndef TP_MP_LIGHT_DRAWS_H
#define TP_MP_LIGHT_DRAWS_H
#include "include/glsl_cpp.h"

#define TP_MPLD_BINDING_PARAMS 0   // LightDrawParams (per view)
#define TP_MPLD_BINDING_LIGHTS 1   // LightDrawLight per local light, in light order (per view)
#define TP_MPLD_BINDING_DRAWS 2    // LightDrawDraw per opaque then masked draw (per view)
#define TP_MPLD_BINDING_COMMANDS 3 // VkDrawIndexedIndirectCommand (5 words): per light a region
#define TP_MPLD_BINDING_COUNTS 4   // uint per (light, run): its commands written
#define TP_MPLD_BINDING_MESHES                                                                     \
    5                              // uvec2 per light: the opaque and masked draws it touches,
                                   // and the triangles its commands draw
#define TP_MPLD_BINDING_MESHLETS 6 // the scene's MeshletGpu[] (include/meshlets.h)

#define TP_MPLD_GROUP 64        // lights per workgroup (one invocation walks one light's draws)
#define TP_MPLD_COMMAND_WORDS 5 // sizeof(VkDrawIndexedIndirectCommand) / 4
// At most this many commands per draw and light: runs of the meshlets the light reaches
// (fewer where lights x draws x this many commands would pass the pass's memory limit).
#define TP_MPLD_MAX_SPANS_PER_DRAW 16u
// A light that touches every draw on screen: a directional light beyond the base pass's.
#define TP_MPLD_FLAG_ALL 1u

#ifndef TP_GLSL
namespace tp::gpu {
#endif

TP_STRUCT(LightDrawParams) {
    uint lightCount; // local lights (rows of LightDrawLight)
    uint drawCount;  // rows of LightDrawDraw: a light's region holds drawCount x spansPerDraw
    uint runCount;   // runs of draws of one cull mode: counts per light
    uint boxTest;    // 1: the sphere-box test too (1x); 0: screen rectangles only (MSAA)
    uint spansPerDraw; // commands a draw may take in a light's region (light_draws.comp)
    // 1: only the meshlets a light reaches (every shaded point lies on its triangle: 1x and
    // sample-rate MSAA); 0: the meshlets whose fragments can fall in its scissor (pixel-rate
    // MSAA shades at the pixel centre, which may lie off the triangle, at a grazing angle far
    // off it).
    uint meshletReach;
    uint pad0;
    uint pad1;
};

// A pixel rectangle [x0, x1) x [y0, y1) is (x0, y0, x1, y1), as mp::ScreenRect.
TP_STRUCT(LightDrawLight) {
    ivec4 rect;  // the light's scissor (empty: off-screen or behind, touches nothing)
    vec4 sphere; // camera-relative centre, range
    uint flags;  // TP_MPLD_FLAG_*
    uint light;  // its index in the scene's lights (the blended light draws read it)
    uint pad1;
    uint pad2;
};

TP_STRUCT(LightDrawDraw) {
    ivec4 rect;  // the box's screen rectangle (empty: off-screen this view)
    vec4 boxMin; // camera-relative box (SceneGpu::toShading), w unused
    vec4 boxMax;
    uint firstIndex; // the draw's range in the scene's index buffer
    uint indexCount;
    int vertexOffset;
    uint material;   // written as the command's firstInstance (scene_material_vert)
    uint run;        // its run: consecutive draws of one cull mode, in draw order
    uint runFirst;   // the run's first draw: its commands' offset in a light's region
    uint firstMeshlet; // its meshlets (SceneGpu::buildMeshlets), in the meshlet index buffer
    uint meshletCount;
};

#ifndef TP_GLSL
static_assert(sizeof(LightDrawParams) == 32);
static_assert(sizeof(LightDrawLight) == 48);
static_assert(offsetof(LightDrawLight, flags) == 32);
static_assert(offsetof(LightDrawLight, light) == 36);
static_assert(sizeof(LightDrawDraw) == 80);
static_assert(offsetof(LightDrawDraw, firstIndex) == 48);
static_assert(offsetof(LightDrawDraw, run) == 64);
#endif

// The light plan's rules (multipass_forward/light_plan.cpp), one copy for the CPU plan and the
// GPU pass so both select the same draws. Rectangles as above.
TP_INLINE bool mpRectEmpty(ivec4 r) {
    return r.z <= r.x || r.w <= r.y;
}
TP_INLINE bool mpRectsOverlap(ivec4 a, ivec4 b) {
    return a.x < b.z && b.x < a.z && a.y < b.w && b.y < a.w;
}
// Whether the sphere reaches the box (the closest point of the box within the range).
// `precise` on the GPU: no fused multiply-add, so both sides round alike (the C++ build
// contracts nothing on x86-64 without FMA in its target).
#ifdef TP_GLSL
#define TP_MPLD_PRECISE precise
#else
#define TP_MPLD_PRECISE
#endif
TP_INLINE bool mpSphereTouchesBox(vec3 centre, float radius, vec3 lo, vec3 hi) {
    TP_MPLD_PRECISE vec3 d = centre - clamp(centre, lo, hi);
    TP_MPLD_PRECISE float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
    TP_MPLD_PRECISE float r2 = radius * radius;
    return d2 <= r2;
}

#ifdef TP_GLSL
// Whether light `l` lights draw `d` this view: the light plan's `touches` (light_plan.cpp), for
// the opaque and masked draws (light_draws.comp) and the blended ones (blended_light_draws.comp).
bool mpLightTouchesDraw(LightDrawLight l, LightDrawDraw d, bool boxTest) {
    if (mpRectEmpty(l.rect) || mpRectEmpty(d.rect)) return false; // off-screen: in no pass
    if ((l.flags & TP_MPLD_FLAG_ALL) != 0u) return true;
    return mpRectsOverlap(l.rect, d.rect) &&
           (!boxTest || mpSphereTouchesBox(l.sphere.xyz, l.sphere.w, d.boxMin.xyz, d.boxMax.xyz));
}
#endif

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
