// The shadow faces' meshlet cull (core/passes/shadow_cull.h, shadow/shadow_cull.comp): its
// bindings in set TP_SET_PASS, its table of (face, draw) rows and what it writes.
// docs/shadows.md, "Culling the faces' meshlets".
#ifndef TP_SHADOW_CULL_H
#define TP_SHADOW_CULL_H
#include "include/glsl_cpp.h"

#define TP_SC_BINDING_COMMANDS 0 // VkDrawIndexedIndirectCommand[] (5 words), per row a range
#define TP_SC_BINDING_COUNTS 1   // uint per row: its commands written (the draw count)
#define TP_SC_BINDING_STATS 2    // ShadowCullStats per row
#define TP_SC_BINDING_MESHLETS 3 // MeshletGpu[] (the scene's, include/meshlets.h)
#define TP_SC_BINDING_ROWS 4     // ShadowCullRow[]: one workgroup each
#define TP_SC_BINDING_FACES 5    // ShadowFace[] (include/shadows.h)

// Invocations per workgroup (meshlets tested at once). A row holds one draw's meshlets for one
// face, a handful on the courtyard-small (7 on average), so one 8-lane batch: on lavapipe (8
// lanes, every barrier a switch between a group's batches) 64 took 55 ms for 563 rows, 8 took
// 2.5 ms (courtyard-small, 16 shadowed lights, docs/shadows.md).
#define TP_SC_GROUP 8
#define TP_SC_COMMAND_WORDS 5    // sizeof(VkDrawIndexedIndirectCommand) / 4
// A meshlet is culled by its light's range only when its sphere lies farther from the light
// than range * (1 + TP_SC_RANGE_FOOTPRINTS * params.x): no fragment that far can darken a PCF
// tap of a receiver the light reaches (docs/shadows.md derives 3 footprints; 4 leaves one for
// rounding).
#define TP_SC_RANGE_FOOTPRINTS 4.0f

#ifndef TP_GLSL
namespace tp::gpu {
#endif

// One (face, draw) pair the CPU's per-draw test kept (ShadowMaps::cullFaces): its meshlets are
// culled against the face. A row of meshletCount 0 (padding to the planned capacity) writes a
// count of 0 and is never drawn; its firstCommand is the end of the last real row's, so the
// rows stay sorted by firstCommand (the compute rasterizer finds a command's row by bisection).
TP_STRUCT(ShadowCullRow) {
    uint firstMeshlet; // the draw's meshlets in the scene's MeshletGpu[]
    uint meshletCount;
    uint firstCommand; // its range of commands (meshletCount long)
    int vertexOffset;  // DrawItem::vertexOffset, copied into each command
    uint face;         // in ShadowFace[]
    uint material;     // MaterialGpu index (the compute rasterizer's alpha test)
    uint flags;        // TP_SR_FLAG_* (shadow/shadow_raster.h): masked
    uint pad0;
};

// Per row and render: meshlets kept, culled by the face's frustum, culled by the light's range
// (tested where the frustum kept them), triangles of the kept ones.
TP_STRUCT(ShadowCullStats) {
    uint submitted;
    uint frustumCulled;
    uint rangeCulled;
    uint triangles;
};

#ifndef TP_GLSL
static_assert(sizeof(ShadowCullRow) == 32);
static_assert(offsetof(ShadowCullRow, face) == 16);
static_assert(sizeof(ShadowCullStats) == 16);
} // namespace tp::gpu
#endif
#endif
