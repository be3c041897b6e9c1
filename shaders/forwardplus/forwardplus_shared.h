// Forward+: structs, set-1 bindings and constants shared by C++ and GLSL.
// Included by this pipeline's C++ and GLSL only (never by shared.h); same rules as
// shared.h (TP_STRUCT, static_asserts on the C++ side).
#ifndef TP_FORWARDPLUS_SHARED_H
#define TP_FORWARDPLUS_SHARED_H
#include "include/shared.h"
#include "include/light_assign.h"
#ifndef TP_GLSL
namespace tp::gpu {
#endif

// ---- set 1 of the Forward+ passes ----
#define TP_FP_BINDING_TILES 0   // buffer FpTileLists[tileCount]: per-tile counts, starts, drops, depth bounds
#define TP_FP_BINDING_INDICES 1 // buffer uint[]: light indices (compact, fixed) or nodes (linked: {light, next})
#define TP_FP_BINDING_PARAMS 2  // buffer FpParams + uint data[] (uploaded once per configuration)
#define TP_FP_BINDING_DEPTH 3   // culling only: the prepass depth (sampler2D, or sampler2DMS with MSAA)
#define TP_FP_BINDING_COUNTER 4 // culling only, "linked" layout: node-pool allocation counter
#define TP_FP_BINDING_CLUSTER_MASKS 5 // clustered only: buffer uint[]: per tile and slice, a bitmask over the tile list
#define TP_FP_BINDING_BLEND_BOUNDS 6  // culling only: blended depth bounds (light_assign.h: TP_LA_BLEND_*; a stand-in without blended draws)
#define TP_FP_BINDING_SPHERES 7 // light_spheres (written), culling (read): buffer vec4[light]: view-space centre, padded range
#define TP_FP_BINDING_LIGHTS_UBO 8 // shading only: the scene's lights again, as a uniform buffer (TP_FP_SPEC_LIGHTS_UBO)
#define TP_FP_BINDING_CENTRE_BOUNDS 9 // culling only: the opaque fragments' centre distances (core/passes/blended_bounds.h, `opaque`; a stand-in unless TP_FP_SPEC_CENTRE_BOUNDS)
#define TP_FP_BINDING_MATERIALS_UBO 10 // shading only: the scene's materials again, as a uniform buffer (TP_FP_SPEC_MATERIALS_UBO)

// ---- specialization constants (ids after the shared ones) ----
#define TP_FP_SPEC_TWO_LISTS 14 // 1: an opaque and a transparent list per tile (scene has blended materials)
#define TP_FP_SPEC_LAYOUT 15    // TP_FP_LAYOUT_*
#define TP_FP_SPEC_BINNED 16    // culling: 1 = test each tile's candidates (--light-cull binned), 0 = every light
#define TP_FP_SPEC_SLICES 17    // clustered: depth slices per tile
#define TP_FP_SPEC_BLENDED_SPAN 18 // clustered: 1 = the scene has blended surfaces: spans widen to them, front slices
#define TP_FP_SPEC_SPHERES 19 // culling: 1 = read each light's sphere from light_spheres, 0 = compute it per candidate
#define TP_FP_SPEC_CULL_LANES 20 // light_culling_subgroup: workgroup size = the device's subgroup size (<= 64)
#define TP_FP_SPEC_LIGHTS_UBO 21 // shading: 1 = read the lights from TP_FP_BINDING_LIGHTS_UBO, 0 = from the scene's storage buffer
#define TP_FP_SPEC_HDR16 22 // shading: 1 = hdr is RGBA16F (--hdr fp16, auto): sums saturate at 65,504; 0 = RGBA32F
#define TP_FP_SPEC_CENTRE_BOUNDS 23 // culling: 1 = widen each tile's opaque range to its opaque fragments' centre distances (--msaa-shading pixel under MSAA)
#define TP_FP_SPEC_MATERIALS_UBO 24 // shading: 1 = read the draw's material from TP_FP_BINDING_MATERIALS_UBO, 0 = from the scene's storage buffer
#define TP_FP_SPEC_NO_LIGHTS 25 // shading: 1 = the plan has no light at all: the light loop and the tile list's loads are compiled out
// shading: fp_params' directionalCount and tilesX, tilesY as constants (fixed for a plan): lavapipe
// loads a storage buffer per lane even at a uniform address (docs/efficiency.md)
#define TP_FP_SPEC_DIRECTIONAL 26
#define TP_FP_SPEC_TILES_X 27
#define TP_FP_SPEC_TILES_Y 28
// Lights the uniform-buffer copy holds: 64 KiB of LightGpu (std140 and std430 agree: 64 bytes).
// Materials the uniform-buffer copy holds: 40 KiB of MaterialGpu (std140 and std430 agree: 80 bytes,
// no array or scalar member that std140 would pad).

#define TP_FP_LAYOUT_COMPACT 0u // per-tile offsets from a conservative CPU bound: never drops
#define TP_FP_LAYOUT_FIXED 1u   // tileCapacity slots per tile (AMD ForwardPlus11); drops counted
#define TP_FP_LAYOUT_LINKED 2u  // head per tile + node pool with an atomic counter

// The culling takes each tile's candidates in batches, one dispatch each, in the scene's
// DrawPush push constant: candidates [first, end), and initial = 1 on the pass's first
// dispatch (the lists start empty). lavapipe ends an invocation after 65,535 loop iterations
// in total (core/passes/tiled_lighting.h), and one invocation culls a whole tile.
#define TP_FP_CULL_FIRST pad0
#define TP_FP_CULL_END pad1
#define TP_FP_CULL_INITIAL pad2
// light_spheres: the number of lights (one invocation each), in the same push constant.
#define TP_FP_SPHERE_COUNT pad0
// Loop iterations one culling dispatch may spend on its candidates: half of lavapipe's
// limit (the depth bounds take at most 32 * 32 * 4 + 32 * 32 + 32 more).
#define TP_FP_CULL_LOOP_BUDGET 32768u

// What the culling pass leaves for each tile. list[TP_LA_OPAQUE] is bounded by the tile's
// [min, max] depth, list[TP_LA_TRANSPARENT] by the tile's blended depth bounds (empty where
// no blended fragment is shaded; light_assign.glsl: LaBlendedBounds). Each is light assignment's one list header
// (include/light_assign.h): count kept (never more than the storage holds); start = first
// slot in indices[] (compact, fixed) or the head node (linked: count bounds the walk);
// dropped = passed the test but did not fit (fixed capacity, pool overflow); found = both.
TP_STRUCT(FpTileLists) {
    LaListHeader list[2];
    float nearDepth; // opaque depth bounds, reverse-Z: nearDepth >= farDepth;
    float farDepth;  // nearDepth == 0: no geometry in the tile (sky), opaque list empty
    float sliceNear;  // clustered: view distance of the nearest opaque depth (1e30 without geometry; light_assign.glsl: laSliceOf)
    float sliceScale; // clustered: range slices per unit of log(distance / sliceNear); 0 when tiled
    float frontNear;  // clustered with blended surfaces: where the front slices start (light_assign.glsl: laFrontNear)
    float pad0, pad1, pad2;
};

// Uploaded once per configuration; followed in the same buffer by uint data[]:
//   data[0 .. directionalCount)                     directional light indices (shaded by every fragment)
//   data[directionalCount .. + localCount)          point/spot light indices (culled)
//   data[tileOffsetBase .. + tileCount + 1)         compact layout or binned culling: first slot of each
//                                                   tile (prefix sum of the conservative bound)
//   data[candidateBase + offset[t] .. + offset[t+1]) binned culling: tile t's candidate light indices, ascending
//   data[maskOffsetBase .. + tileCount + 1)         clustered: first word of tile t's slice bitmasks in the
//                                                   mask buffer; (next - first) / slices words per slice
TP_STRUCT(FpParams) {
    uvec4 tiles;  // tilesX, tilesY, tileCount, tileSize
    uvec4 lights; // directionalCount, localCount, tileOffsetBase, tileCapacity (fixed layout)
    uvec4 lists;  // listStride (slots of list 0 before list 1), poolNodes (linked), candidateBase (binned), maskOffsetBase (clustered)
};

#ifndef TP_GLSL
static_assert(sizeof(FpTileLists) == 64);
static_assert(offsetof(FpTileLists, nearDepth) == 32);
static_assert(sizeof(FpParams) == 48);
#endif

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
