// The tiled-lighting pass of a surface source and the hybrid blended pass of the pass library
// (core/passes/tiled_lighting.h, blended_forward.h): their set-1 bindings, specialization
// constants and buffer layouts, shared by C++ and GLSL (same rules as shared.h). Their
// shaders are shaders/deferred/tiled_lighting.comp and transparent.frag (deferred's G-buffer is
// the first surface source); the TP_DEF_ prefix is theirs from there.
#ifndef TP_TILED_LIGHTING_H
#define TP_TILED_LIGHTING_H
#include "include/shared.h"
#ifndef TP_GLSL
namespace tp::gpu {
#endif

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
// most this many, one dispatch each (core/passes/tiled_lighting.h says why and how big).
#define TP_DEF_TILE_LIGHT_CAPACITY 4096u
// The batch of one tiled lighting dispatch: lights [first, end) of the scene's light
// buffer (binned: candidates [first, end) of each tile), in the scene's DrawPush push
// constant (the dispatches share one pipeline).
#define TP_DEF_LIGHT_FIRST pad0
#define TP_DEF_LIGHT_END pad1

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
