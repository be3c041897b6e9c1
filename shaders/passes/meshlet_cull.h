// The meshlet cull pass (core/passes/meshlet_cull.h, passes/meshlet_cull.comp): its bindings
// in set TP_SET_PASS, its table of draws and the layout of what it writes. docs/geometry.md.
#ifndef TP_MESHLET_CULL_H
#define TP_MESHLET_CULL_H
#include "include/glsl_cpp.h"

#define TP_MC_BINDING_COMMANDS 0 // VkDrawIndexedIndirectCommand[] (5 words), per draw a range
#define TP_MC_BINDING_COUNTS 1   // uint per draw: its commands written (the draw count)
#define TP_MC_BINDING_STATS 2    // MeshletCullStats per draw
#define TP_MC_BINDING_MESHLETS 3 // MeshletGpu[] (the scene's, include/meshlets.h)
#define TP_MC_BINDING_DRAWS 4    // CullDraw[]: the draws culled, one workgroup each
// --cull-geometry full only (TP_MC_PHASE 1 and 2):
#define TP_MC_BINDING_HISTORY 5  // uint per meshlet (a draw's range of commands): TP_MC_HISTORY_*
#define TP_MC_BINDING_PYRAMID 6  // the late phase: the depth pyramid (passes/depth_pyramid.h)

#define TP_MC_GROUP 64           // invocations per workgroup: meshlets tested at once
#define TP_MC_COMMAND_WORDS 5    // sizeof(VkDrawIndexedIndirectCommand) / 4
#define TP_MC_FLAG_CONE 1u       // the draw may be cone-culled (single-sided material)
// Each command's firstInstance is its meshlet's first triangle in the meshlet index buffer
// (gl_InstanceIndex in the vertex shader; 0 without): the visibility pass maps gl_PrimitiveID,
// which restarts at 0 with every indirect draw, back to the draw's own triangle.
#define TP_MC_FLAG_FIRST_TRIANGLE 2u

// The phases (the shader's TP_MC_PHASE): frustum and cone only (--cull-geometry frustum); the
// early phase of `full` (what was visible last frame); its late phase (the rest, and occlusion
// against the pyramid of what the early phase drew).
#define TP_MC_PHASE_FRUSTUM 0
#define TP_MC_PHASE_EARLY 1
#define TP_MC_PHASE_LATE 2
// A meshlet's history word: visible at the end of the last frame (the late phase writes it);
// drawn by this frame's early phase (the early phase sets it, the late phase reads and clears
// it: the late phase draws exactly the visible meshlets the early one did not).
#define TP_MC_HISTORY_VISIBLE 1u
#define TP_MC_HISTORY_DRAWN_EARLY 2u

#ifndef TP_GLSL
namespace tp::gpu {
#endif

TP_STRUCT(CullDraw) {
    uint firstMeshlet;  // the draw's meshlets in the scene's MeshletGpu[]
    uint meshletCount;
    uint firstCommand;  // its range of commands (meshletCount long) in the commands buffer
    int vertexOffset;   // DrawItem::vertexOffset, copied into each command
    uint flags;         // TP_MC_FLAG_*
    uint pad0;
    uint pad1;
    uint pad2;
};

// Per draw, frame and phase: meshlets kept (drawn), culled by the frustum, culled by the normal
// cone (tested only where the frustum kept them), triangles of the kept meshlets, culled by
// occlusion (the late phase only: tested where the frustum and cone kept them). The late phase
// counts the culled among the meshlets the early phase did not draw, so over both phases
// submitted + frustum + cone + occlusion = the draw's meshlets.
TP_STRUCT(MeshletCullStats) {
    uint submitted;
    uint frustumCulled;
    uint coneCulled;
    uint triangles;
    uint occlusionCulled;
    uint pad0;
    uint pad1;
    uint pad2;
};

#ifndef TP_GLSL
static_assert(sizeof(CullDraw) == 32);
static_assert(offsetof(CullDraw, vertexOffset) == 12);
static_assert(sizeof(MeshletCullStats) == 32);
} // namespace tp::gpu
#endif
#endif
