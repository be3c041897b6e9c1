// Light assignment (core/lightassign, include/light_assign.glsl): the structs and constants
// of tile light lists that cross between C++ and GLSL. Same rules as shared.h (TP_STRUCT,
// static_asserts on the C++ side). Pipeline-free: a pipeline's own bindings that hold
// these lists live in its own header.
#ifndef TP_LIGHT_ASSIGN_H
#define TP_LIGHT_ASSIGN_H
#include "include/shared.h" // TP_STRUCT
#ifndef TP_GLSL
namespace tp::gpu {
#endif

// The two depth ranges a tile's lights are culled against (light_assign.glsl:
// laOpaqueRange, laTransparentRange).
#define TP_LA_OPAQUE 0u      // the tile's [nearest, farthest] opaque depth; empty over the sky
#define TP_LA_TRANSPARENT 1u // the tile's blended depth bounds (laBlendedBounds; empty without blended fragments)

// Clustered with blended surfaces: 1 / TP_LA_FRONT_SLICE_SHARE of the slices (at least one)
// cut the tile's front region, nearest blended fragment (laFrontNear) to nearest opaque
// depth (light_assign.glsl: laFrontSlices); the rest cut the opaque range.
#define TP_LA_FRONT_SLICE_SHARE 4u

// Blended depth bounds (core/passes/blended_bounds.h, shaders/passes/blended_bounds.frag): per
// tile, the nearest and farthest view distance (-z, > 0) of the blended fragments that the
// blended shading pass will shade, as float bits (non-negative floats order like their
// bits): words [0, tiles) the minimum (+inf bits = 0x7f800000: no blended fragment),
// words [tiles, 2 * tiles) the maximum (0 without). Cleared by a transfer fill every frame.
#define TP_LA_BLEND_BINDING_BOUNDS 0 // the bounds pass's own set (TP_SET_PASS): buffer uint[2 * tiles]
// 1: one atomic pair per tile a subgroup meets, not per fragment (passes/blended_bounds.glsl;
// a GPU: GpuContext::reducesFragmentsBySubgroup).
#define TP_LA_SPEC_BLEND_BY_SUBGROUP 6
#define TP_LA_BLEND_EMPTY 0x7f800000u // +inf: the minimum of a tile with no blended fragment
// Relative padding of the recorded distances (light_assign.glsl: laBlendedBounds): the
// bounds pass and the shading pass compute the distance with the same expression from the
// same interpolants, so they differ by the rounding of that expression only (a few ulps).
#define TP_LA_BLEND_PAD 1e-4

// A compact light list in one uint buffer: the headers of every tile first, then the light
// indices. Tile t's header is words [t * TP_LA_HEADER_WORDS, (t + 1) * TP_LA_HEADER_WORDS);
// its lights are words [start, start + count), start = headers' size + the tile's offset
// (a prefix sum of the conservative per-tile bound, core/lightassign/compact_layout.h).
TP_STRUCT(LaListHeader) {
    uint count;   // lights stored (never more than the tile's slots)
    uint start;   // first light index word in the buffer
    uint dropped; // lights that passed the test but found no slot (0 with a conservative bound)
    uint found;   // lights that passed the test (count + dropped)
};
#define TP_LA_HEADER_WORDS 4u

#ifndef TP_GLSL
static_assert(sizeof(LaListHeader) == TP_LA_HEADER_WORDS * 4);
static_assert(offsetof(LaListHeader, start) == 4);
static_assert(offsetof(LaListHeader, dropped) == 8);
} // namespace tp::gpu
#endif
#endif
