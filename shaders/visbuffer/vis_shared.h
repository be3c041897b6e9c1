// The visibility buffer's GPU interface (C++ and GLSL): the id it stores per sample, its
// per-draw table and its set-1 bindings beside the tiled lighting pass's
// (passes/tiled_lighting.h), whose bindings it shares.
#ifndef TP_VIS_SHARED_H
#define TP_VIS_SHARED_H
#include "include/glsl_cpp.h"

#ifndef TP_GLSL
namespace tp::gpu {
#endif

// Packed id per sample: (draw + 1) << triangleBits | triangle, 0 = no geometry. `draw` indexes
// the VisDraw table, `triangle` is gl_PrimitiveID within that draw. The split is chosen per
// scene (visbuffer/draw_table.h): the fewest triangle bits that hold its largest draw, the
// rest for the draws. Stored as the fp32 value of that integer in an R32_SFLOAT target, exact
// below 2^24 (TP_VIS_ID_BITS): integer colour targets under MSAA are optional
// (framebufferIntegerColorSampleCounts is 1x only on lavapipe), float ones are not, and an
// integer-valued float is a normal number no conversion, flush or NaN rule can touch. A scene
// that needs more bits is refused.
TP_STRUCT(VisDraw) {
    uint firstIndex;   // in the scene's index buffer
    int vertexOffset;  // added to each index
    uint material;     // MaterialGpu index
    uint pad0;
};

#define TP_VIS_ID_BITS 24

// ---- set 1 of the visibility resolve (the tiled lighting pass with the vis reader) ----
#define TP_VIS_BINDING_IDS 0      // sampler (sampler2D / sampler2DMS): packed ids as fp32
#define TP_VIS_BINDING_INDICES 14 // buffer uint[]: the scene's index buffer
#define TP_VIS_BINDING_DRAWS 15   // buffer VisDraw[]: the draws the ids name
#define TP_VIS_BINDING_BLEND_HEADS 16 // buffer uint[pixels]: each pixel's first blended node + 1 (0: none)
#define TP_VIS_BINDING_BLEND_NODES 17 // buffer uvec2[capacity]: the blended fragments' nodes
#define TP_VIS_BINDING_BLEND_COUNTERS 18 // buffer uint[TP_VIS_BLEND_COUNTER_WORDS]

// ---- set 1 of the visibility pass, drawing culled meshlets (--cull-geometry frustum) ----
#define TP_VIS_BINDING_SOURCE_TRIANGLES 0 // buffer uint[]: SceneGpu::meshletSourceTriangleBuffer

// ---- blended fragment lists (--vis-blended compute) ----
// The blended_ids pass appends one node per blended fragment (a primitive covering a pixel
// in front of the opaque depth) to its pixel's list: word 0 the fragment's id (the same
// packing as the visibility ids; blended draws have rows after the opaque and masked ones)
// with its coverage mask in the top 8 bits, word 1 the next node + 1 (0: end). The counters:
// fragments met, fragments dropped (the pool was full: counted, never silent), the pool's
// capacity in nodes, and the most fragments one pixel composited (written by the resolve).
#define TP_VIS_BLEND_COUNTER_WORDS 4
#define TP_VIS_BLEND_APPENDED 0
#define TP_VIS_BLEND_DROPPED 1
#define TP_VIS_BLEND_CAPACITY 2
#define TP_VIS_BLEND_MAX_DEPTH 3
#define TP_VIS_BLEND_COVERAGE_SHIFT 24 // = TP_VIS_ID_BITS: ids below, up to 8 samples above

// ---- specialization constants (ids after deferred's 11..18, which the tiled pass sets) ----
#define TP_VIS_SPEC_TRIANGLE_BITS 19 // low bits of an id that hold the triangle
#define TP_VIS_SPEC_DERIVATIVES 20 // the resolve's texture footprint: TP_VIS_DERIVATIVES_* (--vis-derivatives)
// 1: the resolve samples a material's textures in one walk of the array (a CPU device such as
// lavapipe, where every sample site costs every lane); 0: one walk a slot (a GPU, where a
// branch no lane takes costs nothing and the one walk's five texels cost registers).
#define TP_VIS_SPEC_ONE_TEXTURE_WALK 33
// 1: the visibility pass leaves the ids of samples it does not write as they were (no clear:
// visibility_pass.h), so the resolve takes a sample's id only where its depth holds geometry.
#define TP_VIS_SPEC_IDS_BY_DEPTH 34
// --vis-edges (vis_settings.h: resolveEdges; auto is 1 on a GPU, 0 on a CPU device). 1 (split):
// under MSAA at pixel rate with the blended fragments composited in compute, only the edges
// whose pixel has a blended list are lit one invocation a pixel, the others flattened (a
// surface an invocation); 0 (pixel; on lavapipe the flattened rounds cost more than the lanes
// they fill): every edge one invocation a pixel (tiled_lighting_main.glsl: shadeTile).
#define TP_VIS_SPEC_SPLIT_EDGES 37

// ---- the uv derivatives textureGrad is given (--vis-derivatives) ----
#define TP_VIS_DERIVATIVES_ANALYTIC 0     // d(uv)/dx, d(uv)/dy at the shaded location itself
#define TP_VIS_DERIVATIVES_QUAD_FINE 1    // differences over the 2x2 quad: the pixel's row and column pair
#define TP_VIS_DERIVATIVES_QUAD_COARSE 2  // differences over the 2x2 quad: its top row and left column

#ifndef TP_GLSL
static_assert(sizeof(VisDraw) == 16);
} // namespace tp::gpu
#endif
#endif
