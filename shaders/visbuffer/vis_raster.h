// The visibility buffer's compute rasterizer (--vis-raster compute|hybrid; visbuffer/
// raster_pass.h, docs/visbuffer.md "The compute rasterizer"): its bindings, its tables and the
// layout of what it writes, for C++ and GLSL.
#ifndef TP_VIS_RASTER_H
#define TP_VIS_RASTER_H
#include "include/glsl_cpp.h"
#include "include/raster_triangle.h"

// Triangles per chunk: one workgroup of vis_raster.comp, one invocation per triangle. A chunk
// lies in one draw (or, culled, in one meshlet of at most 124 triangles).
#define TP_VR_GROUP 128
// The triangle's constants are the shared rasterizer's (include/raster_triangle.h: the large
// triangles' group, the small triangles' size, the guard band; the subpixel bits' constant).
#define TP_VR_BIG_GROUP TP_RT_BIG_GROUP
#define TP_VR_SMALL_PIXELS TP_RT_SMALL_PIXELS
#define TP_VR_GUARD_PIXELS TP_RT_GUARD_PIXELS

// ---- set 1 of vis_raster and vis_raster_big ----
#define TP_VR_BINDING_SAMPLES 0  // uint64_t[pixels * samples]: (depth bits << 32) | ~id
#define TP_VR_BINDING_LIST 1     // uint[]: counters, then the listed triangles (uvec4 each)
#define TP_VR_BINDING_ARGS 2     // uint[4]: the listed triangles' dispatch (compute) or draw (hybrid)
#define TP_VR_BINDING_INDICES 3  // uint[]: the scene's index buffer (or the meshlet index buffer)
#define TP_VR_BINDING_CHUNKS 4   // RasterChunk[]
#define TP_VR_BINDING_ROWS 5     // RasterRow[]: per VisDraw row, its flags and material
#define TP_VR_BINDING_SOURCE_TRIANGLES 6 // culled: SceneGpu::meshletSourceTriangleBuffer
#define TP_VR_BINDING_COMMANDS 7 // culled: meshlet_cull's indexed indirect commands
#define TP_VR_BINDING_COUNTS 8   // culled: meshlet_cull's commands per draw

// ---- set 1 of vis_raster_merge and vis_raster_hw (visbuffer/raster_merge_pass.h) ----
#define TP_VR_BINDING_VIS_SAMPLES 1 // the samples above, read by the merge
#define TP_VR_BINDING_VIS_LIST 2    // hybrid: the listed triangles the hardware draws

// ---- set 1 of vis_raster_order (hybrid: the staged triangles, in triangle order, for the
// hardware's draw) ----
#define TP_VR_BINDING_ORDER_STAGED 0 // the list buffer above, hybrid's staged layout (below)
#define TP_VR_BINDING_ORDER_LIST 1   // uvec4 per listed triangle, in the order of the draws
#define TP_VR_BINDING_ORDER_ARGS 2   // the hardware draw's arguments (its vertex count)

// ---- set 1 of vis_raster_seed (1x: the samples into the targets by a copy) ----
#define TP_VR_BINDING_SEED_SAMPLES 0 // the samples above
#define TP_VR_BINDING_SEED 1         // float[pixels]: the depths, for the copy
#define TP_VR_BINDING_SEED_IDS 2     // the id image (R32_SFLOAT, storage)

// ---- the list buffer: TP_VR_LIST_HEADER words of counters, then uvec4 per listed triangle:
// its three vertex indices (vertexOffset added) and its id ----
// In hybrid mode the slots are staged per chunk instead, so that the hardware draws the listed
// triangles in one order whatever order the workgroups ran in (its depth test keeps the first
// of equal depths, and what its early test rejects is counted): after the header, each chunk's
// listed count (a word a chunk), then TP_VR_GROUP slots a chunk, filled in lane order;
// vis_raster_order packs them into the hardware's list, chunk after chunk.
#define TP_VR_LIST_HEADER 8
#define TP_VR_COUNTERS 4         // the words below, read back for the report
#define TP_VR_COUNT_SMALL 0      // triangles rasterized by their own invocation
#define TP_VR_COUNT_BIG 1        // triangles listed (vis_raster_big or the hardware)
#define TP_VR_COUNT_CULLED 2     // back-facing, zero-area, outside the view or between samples
#define TP_VR_COUNT_CLIPPED 3    // crossing the near plane or the guard band (clipped)
#define TP_VR_LIST_SLOTS 4       // compute: the listed triangles' count (their slots)
#define TP_VR_ATOMICS_SMALL 5    // 64-bit atomic max issued by vis_raster
#define TP_VR_ATOMICS_BIG 6      // 64-bit atomic max issued by vis_raster_big

// RasterRow.flags
#define TP_VR_FLAG_DOUBLE_SIDED 1u
#define TP_VR_FLAG_MASKED 2u // alpha-tested per sample (compute mode)

// ---- specialization constants (after the visbuffer's 19, 20; the triangle's own, 21 and 30,
// in include/raster_triangle.h) ----
#define TP_VR_SPEC_HYBRID 22 // 1: listed triangles go to the hardware (draw args), 0: vis_raster_big
#define TP_VR_SPEC_CHUNKS 23 // vis_raster_order: the chunks (vis_raster's workgroups)

#ifndef TP_GLSL
namespace tp::gpu {
#endif

// One workgroup's triangles. Whole draws: triangles [firstTriangle, + count) of VisDraw row
// `row`, their indices at firstIndex + 3 * triangle of the scene's index buffer. Culled
// (--cull-geometry frustum): command `command` of the draw in meshlet_cull's slot `slot`, run
// only if the cull kept that many meshlets.
TP_STRUCT(RasterChunk) {
    uint row;           // VisDraw row (the id's draw)
    uint firstIndex;    // whole: the draw's first index; culled: meshlet_cull's slot
    int vertexOffset;   // added to each index
    uint firstTriangle; // whole: the chunk's first triangle in its draw; culled: command index
    uint count;         // whole: triangles (<= TP_VR_GROUP); culled: the command's place in its range
    uint pad0;
    uint pad1;
    uint pad2;
};

TP_STRUCT(RasterRow) {
    uint flags;    // TP_VR_FLAG_*
    uint material; // MaterialGpu index (the alpha test)
};

#ifndef TP_GLSL
static_assert(sizeof(RasterChunk) == 32);
static_assert(sizeof(RasterRow) == 8);
} // namespace tp::gpu
#endif
#endif
