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
#define TP_LA_TRANSPARENT 1u // the near plane to the farthest opaque depth (unbounded over the sky)

// Clustered with blended surfaces: 1 / TP_LA_FRONT_SLICE_SHARE of the slices (at least one)
// cut the tile's front region, near plane to nearest opaque depth (light_assign.glsl:
// laFrontSlices); the rest cut the opaque range.
#define TP_LA_FRONT_SLICE_SHARE 4u

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
