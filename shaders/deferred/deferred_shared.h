// G-buffer deferred: structs, set-1 bindings and constants shared by C++ and GLSL.
// Included by this pipeline's C++ and GLSL only (never by shared.h); same rules as
// shared.h (TP_STRUCT, static_asserts on the C++ side).
#ifndef TP_DEFERRED_SHARED_H
#define TP_DEFERRED_SHARED_H
#include "include/shared.h"
#ifndef TP_GLSL
#include <cmath>
namespace tp::gpu {
using std::cos;
using std::sin;
#endif
#define TP_PI_DEF 3.14159265358979f

// ---- set 1 of the tiled lighting compute pass ----
#define TP_DEF_BINDING_BASE 0        // sampler: base colour rgb + occlusion a
#define TP_DEF_BINDING_NORMAL 1      // sampler: octahedral normal (compact) or xyz (wide)
#define TP_DEF_BINDING_ROUGH_METAL 2 // sampler: roughness r, metallic g
#define TP_DEF_BINDING_EMISSIVE 3    // sampler: emissive rgb (only when the scene emits)
#define TP_DEF_BINDING_DEPTH 4       // sampler: D32 depth (per sample under MSAA)
#define TP_DEF_BINDING_HDR 5         // storage image: lit radiance (RGBA32F)
#define TP_DEF_BINDING_TRANSPARENT_LISTS 6 // buffer: transparent light lists, compact (include/light_assign.h)
#define TP_DEF_BINDING_DEBUG 7       // storage image RGBA32F: edge mask, roughness, metallic
#define TP_DEF_BINDING_TILE_STATS 8  // buffer uvec4 per tile: opaque lights, transparent lights, edge pixels, overflow
#define TP_DEF_BINDING_EDGE_MASK 9   // sampler: 1x edge mask (volumes lighting under MSAA)
#define TP_DEF_BINDING_LIST_OFFSETS 10 // buffer uint[tileCount + 1]: compact transparent lists' per-tile offsets
#define TP_DEF_BINDING_CANDIDATES 11   // buffer uint[]: binned culling's per-tile candidates (TP_DEF_CAND_*)
#define TP_DEF_BINDING_TRANSPARENT_MASKS 12 // buffer uint[]: clustered blended scenes: slice rows over the transparent lists
#define TP_DEF_BINDING_BLEND_BOUNDS 13 // buffer uint[]: blended scenes: blended depth bounds (light_assign.h: TP_LA_BLEND_*)

// ---- set 1 of the hybrid forward pass (blended materials) ----
#define TP_DEF_FWD_BINDING_LISTS 0   // buffer: transparent light lists, compact (include/light_assign.h)
#define TP_DEF_FWD_BINDING_MASKS 1   // buffer: clustered: slice rows over the transparent lists (a dummy when tiled)
#define TP_DEF_FWD_BINDING_BLEND_BOUNDS 2 // buffer: blended depth bounds (clustered: where the front slices start)
#define TP_DEF_FWD_BINDING_CANDIDATES 3   // buffer: binned culling's candidates (binned: the lists are bitmasks over them)

// Clustered blended scenes (--light-assign clustered): the transparent list of a tile is its
// span list (its blended depth bounds, light_assign.glsl: LaBlendedBounds) and a buffer of
// per-slice bitmask rows over it lets a blended fragment take only its cluster. Words
// [2t, 2t + 1]: tile t's sliceNear and sliceScale (light_assign.glsl: LaSlicing, with front
// slices); then tile t's rows from defClusterRowsBase, `slices` rows of ceil(count / 32)
// words (count: the list's stored lights). The base needs no offsets table: with `offset`
// the list's compact offset (capacity c), floor(offset / 32) + t + ceil(c / 32) <=
// floor((offset + c) / 32) + t + 1, so the tiles' rows never overlap, and the buffer holds
// 2 * tiles + slices * (floor(slots / 32) + tiles) words.
TP_INLINE uint defClusterRowsBase(uint tileCount, uint offset, uint tile, uint slices) {
    return 2u * tileCount + slices * (offset / 32u + tile);
}
// Binned culling (--light-cull binned): a tile's transparent list is a bitmask over its
// candidates (bit p: candidate p, directional lights first, then its run), and its slice
// rows are bitmasks over the candidates too, of as many words as the list's mask (`offset`:
// the mask's first word, the exact prefix sum of ceil(candidates / 32)): 2 * tiles + slices *
// (mask words) in all.
TP_INLINE uint defMaskRowsBase(uint tileCount, uint offset, uint slices) { return 2u * tileCount + slices * offset; }

// ---- specialization constants of the deferred shaders (ids after the scene's 0..2) ----
#define TP_DEF_SPEC_WIDE 11          // 1: wide (fp32, xyz normal) G-buffer, 0: compact
#define TP_DEF_SPEC_SPHERE_SCALE 14  // float bits: volumeSphereVertex scale that circumscribes the unit sphere
#define TP_DEF_SPEC_EVERY_SAMPLE 15  // 1: every pixel with geometry is lit per sample (--msaa-shading sample)
#define TP_DEF_SPEC_BINNED 16        // 1: a tile tests only its candidates (--light-cull binned), 0: every light
#define TP_DEF_SPEC_SLICES 17        // clustered: depth slices per tile; 0: tiled (--light-assign tiled)
#define TP_DEF_SPEC_MASK_WORDS 18    // words of the shared slice masks: TP_DEF_CLUSTER_MASK_WORDS clustered, 1 tiled

// Clustered deferred: per slice, a bitmask over the tile's shared list of this batch, in
// shared memory (8 KiB beside the 16 KiB list): slices * ceil(lights / 32) words, so a
// batch holds at most TP_DEF_CLUSTER_MASK_WORDS * 32 / slices lights. Tiled lighting sizes the
// array to one word (TP_DEF_SPEC_MASK_WORDS), so its groups pay nothing for it.
#define TP_DEF_CLUSTER_MASK_WORDS 2048u

// The candidates buffer (uploaded once per configuration, core/lightassign/tile_candidates.h):
// word TP_DEF_CAND_DIRECTIONAL = D, the directional lights (every tile's first candidates);
// TP_DEF_CAND_OFFSETS = first word of the tileCount + 1 run offsets; TP_DEF_CAND_RUNS = first
// word of the runs; the D directional light indices start at word TP_DEF_CAND_HEADER. Tile
// t's candidate p is directional p when p < D, else run word offsets[t] + p - D.
#define TP_DEF_CAND_DIRECTIONAL 0u
#define TP_DEF_CAND_OFFSETS 1u
#define TP_DEF_CAND_RUNS 2u
#define TP_DEF_CAND_HEADER 4u

// Lights one tile can hold in shared memory: 4096 uints = 16 KiB of the 32 KiB lavapipe
// offers. The tiled lighting pass never meets more: it takes the lights in batches of at
// most this many, one dispatch each (deferred/tiled_lighting.cpp says why and how big).
#define TP_DEF_TILE_LIGHT_CAPACITY 4096u
// The batch of one tiled lighting dispatch: lights [first, end) of the scene's light
// buffer (binned: candidates [first, end) of each tile), in the scene's DrawPush push
// constant (the dispatches share one pipeline).
#define TP_DEF_LIGHT_FIRST pad0
#define TP_DEF_LIGHT_END pad1

// ---- light volumes (classic deferred, `--deferred-lighting volumes`) ----
// Generated from gl_VertexIndex in shaders/deferred/volume.vert; the CPU computes the scale
// that makes the sphere mesh circumscribe the unit sphere and tests both meshes
// (tests/cpu/deferred_volume_mesh_test.cpp). Triangles wind counter-clockwise seen from
// outside, i.e. they are front faces under the scene's conventions (core/gpu/pipelines.h).
#define TP_DEF_SPHERE_STACKS 8u
#define TP_DEF_SPHERE_SLICES 16u
#define TP_DEF_SPHERE_VERTICES (TP_DEF_SPHERE_STACKS * TP_DEF_SPHERE_SLICES * 6u)
#define TP_DEF_CONE_SEGMENTS 16u
#define TP_DEF_CONE_VERTICES (TP_DEF_CONE_SEGMENTS * 6u) // sides + cap fan around its centre

// A UV sphere on the unit sphere (vertices on it: the mesh is inside; scale it by the
// CPU-computed factor to circumscribe). Two triangles per stack x slice quad (one of them
// degenerate at the poles).
TP_INLINE vec3 volumeSphereVertex(uint k) {
    const uint corners[6] = {0u, 1u, 2u, 0u, 2u, 3u}; // (i,j) (i+1,j) (i+1,j+1) (i,j+1)
    uint quad = k / 6u;
    uint c = corners[k % 6u];
    uint i = quad / TP_DEF_SPHERE_SLICES + ((c == 1u || c == 2u) ? 1u : 0u);
    uint j = quad % TP_DEF_SPHERE_SLICES + ((c == 2u || c == 3u) ? 1u : 0u);
    float lat = -0.5f * TP_PI_DEF + TP_PI_DEF * float(i) / float(TP_DEF_SPHERE_STACKS);
    float lon = 2.0f * TP_PI_DEF * float(j) / float(TP_DEF_SPHERE_SLICES);
    return vec3(cos(lat) * cos(lon), sin(lat), cos(lat) * sin(lon));
}

// A cone with its apex at the origin, axis +z, cap at z = 1, whose 16-gon cross-section
// circumscribes the circle of radius 1 at z = 1: it contains the round cone of slope 1.
TP_INLINE vec3 volumeConeVertex(uint k) {
    uint segment = (k / 3u) % TP_DEF_CONE_SEGMENTS;
    uint corner = k % 3u;
    bool cap = k >= TP_DEF_CONE_SEGMENTS * 3u;
    if (corner == 0u) return cap ? vec3(0.0f, 0.0f, 1.0f) : vec3(0.0f);
    // Sides: apex, ring j+1, ring j; cap: centre, ring j, ring j+1 (both outward CCW).
    uint j = segment + ((corner == 1u) != cap ? 1u : 0u);
    float a = 2.0f * TP_PI_DEF * float(j) / float(TP_DEF_CONE_SEGMENTS);
    float r = 1.0f / cos(TP_PI_DEF / float(TP_DEF_CONE_SEGMENTS));
    return vec3(r * cos(a), r * sin(a), 1.0f);
}

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
