// The shadow maps' compute rasterizer (--shadow-raster compute; core/passes/shadow_raster.h,
// docs/shadows.md "Rasterizing the maps in compute"): its bindings in set TP_SET_PASS and the
// layout of what it writes, for C++ and GLSL. The triangle is include/raster_triangle.glsl's.
#ifndef TP_SHADOW_RASTER_H
#define TP_SHADOW_RASTER_H
#include "include/glsl_cpp.h"
#include "include/raster_triangle.h"

#define TP_SR_BINDING_DEPTH 0    // uint[atlas texels]: the depth's float bits, atomicMax; 0 clear
#define TP_SR_BINDING_LIST 1     // uint[]: counters, then the listed triangles (uvec4 each)
#define TP_SR_BINDING_ARGS 2     // uint[4]: shadow_raster_big's dispatch
#define TP_SR_BINDING_INDICES 3  // uint[]: the scene's meshlet index buffer
#define TP_SR_BINDING_ROWS 4     // ShadowCullRow[] (shadow/shadow_cull.h): face, material, flags
#define TP_SR_BINDING_COMMANDS 5 // shadow_cull's indexed indirect commands (5 words each)
#define TP_SR_BINDING_COUNTS 6   // shadow_cull's commands per row
#define TP_SR_BINDING_FACES 7    // ShadowFace[] (include/shadows.h)
#define TP_SR_BINDING_OVERFLOW 8 // uint[command slots]: the meshlets with a triangle the full
                                 // list could not take (their count: TP_SR_OVERFLOW_MESHLETS)

// Triangles per workgroup of shadow_raster.comp: one command slot (a meshlet of at most 124
// triangles) each, an invocation per triangle.
#define TP_SR_GROUP 128
// Command slots per workgroup of shadow_raster.comp, taken in turn. Most slots are empty (a
// row's range holds a slot for each of its meshlets, the kept ones first): a group per slot
// spent the pass launching empty groups (docs/shadows.md, "The empty slots").
#define TP_SR_SLOTS_PER_GROUP 32

// ---- the list buffer: TP_SR_LIST_HEADER words of counters, then uvec4 per listed triangle:
// its three vertex indices (vertexOffset added) and its ShadowCullRow ----
#define TP_SR_LIST_HEADER 12
#define TP_SR_COUNTERS 4        // the words below, read back for the report
#define TP_SR_COUNT_SMALL 0     // triangles rasterized by their own invocation
#define TP_SR_COUNT_BIG 1       // triangles listed for shadow_raster_big
#define TP_SR_COUNT_CULLED 2    // outside the face, zero area or between texel centres
#define TP_SR_COUNT_CLIPPED 3   // crossing the near plane or the face's guard band
#define TP_SR_LIST_SLOTS 4      // the slots taken (may pass the capacity: see OVERFLOW)
#define TP_SR_ATOMICS_SMALL 5   // 32-bit atomic max issued by shadow_raster
#define TP_SR_ATOMICS_BIG 6     // 32-bit atomic max issued by shadow_raster_big
#define TP_SR_OVERFLOW 7        // large triangles the full list could not take: their meshlets
                                // listed in the overflow buffer, whose large triangles
                                // shadow_raster_big rasterizes again (the atomic max is
                                // idempotent: a triangle drawn twice changes nothing)
#define TP_SR_OVERFLOW_MESHLETS 8 // meshlets in the overflow buffer

// ShadowCullRow.flags
#define TP_SR_FLAG_MASKED 1u // alpha-tested per texel

// ---- specialization constants of shadow_raster and shadow_raster_big (the triangle's own, 21
// and 30, in include/raster_triangle.h) ----
#define TP_SR_SPEC_WIDTH 22         // the map's width in texels (the depth buffer's row)
#define TP_SR_SPEC_LOCAL 23         // 1: the faces' `local` rects (one light's map), 0: `atlas`

#endif
