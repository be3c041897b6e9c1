// The tiled-lighting pass of a surface source and the hybrid blended pass of the pass library
// (core/passes/tiled_lighting.h, blended_forward.h): their set-1 bindings, specialization
// constants, buffer layouts and shader variant key, shared by C++, GLSL and CMake (same rules
// as shared.h). Their shaders are in shaders/passes/ (tiled_lighting_*.glsl over a surface
// source's reader, blended_forward.frag); TP_TL_ is the tiled lighting pass's prefix, TP_BF_
// the blended forward pass's.
#ifndef TP_TILED_LIGHTING_H
#define TP_TILED_LIGHTING_H
#include "include/shared.h"
#ifndef TP_GLSL
namespace tp::gpu {
#endif

// ---- set 1 of the tiled lighting compute pass ----
// Bindings 0-3, 9 and 14-23 are the surface source's (its reader declares them:
// deferred_shared.h, visbuffer/vis_shared.h).
#define TP_TL_BINDING_DEPTH 4       // sampler: D32 depth (per sample under MSAA)
#define TP_TL_BINDING_HDR 5         // storage image: lit radiance (RGBA32F)
#define TP_TL_BINDING_TRANSPARENT_LISTS 6 // buffer: transparent light lists, compact (include/light_assign.h)
#define TP_TL_BINDING_DEBUG 7       // storage image RGBA32F: edge mask, roughness, metallic
#define TP_TL_BINDING_TILE_STATS 8  // buffer uvec4 per tile: opaque lights, transparent lights, edge pixels, overflow
#define TP_TL_BINDING_LIST_OFFSETS 10 // buffer uint[tileCount + 1]: compact transparent lists' per-tile offsets
#define TP_TL_BINDING_CANDIDATES 11   // buffer uint[]: binned culling's per-tile candidates (TP_TL_CAND_*)
#define TP_TL_BINDING_TRANSPARENT_MASKS 12 // buffer uint[]: clustered blended scenes: slice rows over the transparent lists
#define TP_TL_BINDING_BLEND_BOUNDS 13 // buffer uint[]: blended scenes: blended depth bounds (light_assign.h: TP_LA_BLEND_*)
#define TP_TL_BINDING_TILE_DEPTH 24  // buffer uvec4 per tile: its depth bounds (the tile_depth_bounds pass writes them)
#define TP_TL_BINDING_LIGHTS_UBO 25  // uniform buffer: the scene's lights again (core/passes/lights_ubo.h; read where TP_TL_SPEC_LIGHTS_UBO)

// The tile depth bounds pass (its set 1: TP_TL_BINDING_DEPTH and TP_TL_BINDING_TILE_DEPTH)
// writes a tile's record: the bit patterns of its nearest and farthest geometry depth
// (reverse-Z: nearest is largest; near 0: no geometry), 1 when some sample sees the sky, 0
// (include/light_assign.glsl: laDepthBoundsWords).

// ---- set 1 of the hybrid forward pass (blended materials) ----
#define TP_BF_BINDING_LISTS 0   // buffer: transparent light lists, compact (include/light_assign.h)
#define TP_BF_BINDING_MASKS 1   // buffer: clustered: slice rows over the transparent lists (a dummy when tiled)
#define TP_BF_BINDING_BLEND_BOUNDS 2 // buffer: blended depth bounds (clustered: where the front slices start)
#define TP_BF_BINDING_LIGHTS_UBO 3  // uniform buffer: the tiled lighting's copy of the lights (read where TP_TL_SPEC_LIGHTS_UBO)
#define TP_BF_BINDING_MATERIALS_UBO 4 // uniform buffer: the materials' copy (core/passes/materials_ubo.h; read where TP_BF_SPEC_MATERIALS_UBO)
#define TP_BF_SPEC_MATERIALS_UBO 36

// Clustered blended scenes (--light-assign clustered): the transparent list of a tile is its
// span list (its blended depth bounds, light_assign.glsl: LaBlendedBounds) and a buffer of
// per-slice bitmask rows over it lets a blended fragment take only its cluster. Words
// [2t, 2t + 1]: tile t's sliceNear and sliceScale (light_assign.glsl: LaSlicing, with front
// slices); then tile t's rows from tlClusterRowsBase, `slices` rows of ceil(count / 32)
// words (count: the list's stored lights). The base needs no offsets table: with `offset`
// the list's compact offset (capacity c), floor(offset / 32) + t + ceil(c / 32) <=
// floor((offset + c) / 32) + t + 1, so the tiles' rows never overlap, and the buffer holds
// 2 * tiles + slices * (floor(slots / 32) + tiles) words.
TP_INLINE uint tlClusterRowsBase(uint tileCount, uint offset, uint tile, uint slices) {
    return 2u * tileCount + slices * (offset / 32u + tile);
}
// The transparent lists and their slice rows are the same under --light-cull binned (light
// indices, in candidate order), except where the tiled pass composites the blended fragments
// itself (the visibility buffer's --vis-blended compute): there, binned, a tile's list is a
// bitmask over its candidates (bit p: candidate p, directional lights first, then its run),
// ceil(candidates / 32) words, and it has no slice rows.

// ---- specialization constants of the pass library's tiled shaders (ids after the scene's 0..2;
// 11 to 14 are the surface sources') ----
#define TP_TL_SPEC_EVERY_SAMPLE 15  // 1: every pixel with geometry is lit per sample (--msaa-shading sample)
#define TP_TL_SPEC_BINNED 16        // 1: a tile tests only its candidates (--light-cull binned), 0: every light
#define TP_TL_SPEC_SLICES 17        // clustered: depth slices per tile; 0: tiled (--light-assign tiled)
#define TP_TL_SPEC_MASK_WORDS 18    // words of the shared slice masks: TP_TL_CLUSTER_MASK_WORDS clustered, 1 tiled
// The workgroup's edge, x and y the same (--tile-group, core/lightassign/knobs.h: 16 on a GPU
// with 16- and 32-pixel tiles, 8 on a CPU device and for 8-pixel tiles).
#define TP_TL_SPEC_GROUP_X 24
#define TP_TL_SPEC_GROUP_Y 25
#define TP_TL_SPEC_LIGHTS_UBO 35    // 1: the lights are read from TP_TL_BINDING_LIGHTS_UBO (a CPU device), 0: from the scene's storage buffer

// Clustered deferred: per slice, a bitmask over the tile's shared list of this batch, in
// shared memory (8 KiB beside the 16 KiB list): slices * ceil(lights / 32) words, so a
// batch holds at most TP_TL_CLUSTER_MASK_WORDS * 32 / slices lights. Tiled lighting sizes the
// array to one word (TP_TL_SPEC_MASK_WORDS), so its groups pay nothing for it.
#define TP_TL_CLUSTER_MASK_WORDS 2048u

// The candidates buffer (uploaded once per configuration, core/lightassign/tile_candidates.h):
// word TP_TL_CAND_DIRECTIONAL = D, the directional lights (every tile's first candidates);
// TP_TL_CAND_OFFSETS = first word of the tileCount + 1 run offsets; TP_TL_CAND_RUNS = first
// word of the runs; the D directional light indices start at word TP_TL_CAND_HEADER. Tile
// t's candidate p is directional p when p < D, else run word offsets[t] + p - D.
#define TP_TL_CAND_DIRECTIONAL 0u
#define TP_TL_CAND_OFFSETS 1u
#define TP_TL_CAND_RUNS 2u
#define TP_TL_CAND_HEADER 4u

// Lights one tile can hold in shared memory: 4096 uints = 16 KiB of the 32 KiB lavapipe
// offers. The tiled lighting pass never meets more: it takes the lights in batches of at
// most this many, one dispatch each (core/passes/tiled_lighting.h says why and how big).
#define TP_TL_TILE_LIGHT_CAPACITY 4096u
// The batch of one tiled lighting dispatch: lights [first, end) of the scene's light
// buffer (binned: candidates [first, end) of each tile), in the scene's DrawPush push
// constant (the dispatches share one pipeline).
#define TP_TL_LIGHT_FIRST pad0
#define TP_TL_LIGHT_END pad1

// The variant key of a tiled lighting shader: a surface source's family (SurfaceSource::
// shaderFamily) + the key + "_comp" names the SPIR-V (and + "_shadow_comp" its shadow-map twin).
// m: 0 one sample per pixel, 1 per-sample surface, 2 per-sample surface and hdr (blended under
// MSAA); e: 1 the surface has an emissive target; t: 1 transparent light lists; d: 1 debug
// outputs; h: "_h16" for an RGBA16F hdr, else empty. The lists-only variant (transparent
// lists alone) has its own key. CMake (shaders/passes/tiled_lighting.cmake) reads these two
// lines to name what it compiles and C++ (core/passes/tiled_lighting.cpp) to name what it
// asks for: the key is declared here only.
#define TP_TL_VARIANT_KEY "_m{m}_e{e}_t{t}_d{d}{h}"
#define TP_TL_LISTS_KEY "_lists_m{m}"

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
