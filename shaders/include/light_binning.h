// Light binning (core/lightassign/light_bins.h on the CPU, core/passes/light_binning.h on the
// GPU): bindings, constants and the conservative tile-rectangle test, compiled as C++ and as
// GLSL so both sides run the same float operations in the same order. Every operation of the
// test is an add, a multiply, a compare or a max (Vulkan requires those correctly rounded
// for 32-bit floats), none is contracted into an FMA (`precise` in GLSL, -ffp-contract=off
// for tile_bound.cpp), and the slab planes are computed once on the CPU and uploaded: so
// the GPU's rectangles are the CPU's, bit for bit, and so are the runs.
#ifndef TP_LIGHT_BINNING_H
#define TP_LIGHT_BINNING_H
#include "include/shared.h"
#ifdef TP_GLSL
#define TP_PRECISE precise
#else
#define TP_PRECISE
namespace tp::gpu {
#endif

// ---- set TP_SET_PASS of the light_binning pass (all storage buffers) ----
#define TP_BIN_BINDING_INPUTS 0  // BinInputs, then vec4 slabs[]: columns lo, columns hi, rows lo, rows hi
#define TP_BIN_BINDING_LOCALS 1  // uint[]: the point/spot light indices, ascending (la::LightClasses::local)
#define TP_BIN_BINDING_COUNTS 2  // uint[2 tiles]: a difference array, then per tile how many rectangles
                                 // cover it; the fill counts it down (its cursor). Then per tile
                                 // the small rectangles counted directly (bin_rects.comp)
#define TP_BIN_BINDING_OFFSETS 3 // uint[tiles + 1 + TP_BIN_NEEDS]: exclusive prefix sum of the counts
                                 // (modulo 2^32: a layout past 2^32 - 1 is refused before any frame,
                                 // from the counts), in the frame clamped to the room; then the needs
#define TP_BIN_BINDING_ROWS 4    // uint[tilesY]: per row of tiles, the sum of its row prefix sums (scans)
#define TP_BIN_BINDING_TARGET 5  // uint[]: tile t's run at words [base + offsets[t], base + offsets[t + 1])
#define TP_BIN_BINDING_RECTS 6   // uvec2[local lights]: each light's rectangle (binPackRect), for the fill
#define TP_BIN_BINDING_WORDS 7   // uint[]: a word layout over the counts (bin_scan_words.comp)

// Push constants (the scene's DrawPush): the target's first word, and per dispatch a range:
// the fill's rows [first, end) of tiles; the long-run sort step's block size k and distance j.
#define TP_BIN_BASE pad0
#define TP_BIN_FIRST pad1
#define TP_BIN_END pad2
// The columns step (the frame): 1 when it publishes the offsets, clamped to the room, into the
// target's words from TP_BIN_OFFSETS_WORD (0: the plan-time sizing, unclamped, unpublished).
#define TP_BIN_PUBLISH materialIndex
#define TP_BIN_OFFSETS_WORD pad1
#define TP_BIN_ROOM pad2
// After the offsets (offsets[tiles + 1 + i]): what the view needed, read after its frames
// (GpuBinning::overflowed): the slots unclamped (modulo 2^32), the longest run.
#define TP_BIN_NEEDS 4u
#define TP_BIN_NEED_SLOTS 0u
#define TP_BIN_NEED_RUN 1u
#define TP_BIN_NEED_WORDS 2u // the word layout's words (when one is published)
#define TP_BIN_NEED_FALLBACKS 3u // not a need: runs the sort gave the bitonic network (a crowded bucket)
// The word layout (bin_scan_words.comp, after the counts): tile t takes
// TP_BIN_WORDS_SCALE * ceil((TP_BIN_WORDS_ADD + counts[t]) / 32) words, a bit per candidate
// (the transparent lists' bitmasks over the directional lights and the run: scale 1; clustered
// Forward+'s slice rows over the run: scale = slices), exclusive prefix sum clamped to
// TP_BIN_WORDS_ROOM, written to the words buffer from its word TP_BIN_WORDS_FIRST (Forward+
// keeps its mask-row offsets inside fp_params).
#define TP_BIN_WORDS_SCALE materialIndex
#define TP_BIN_WORDS_ADD pad0
#define TP_BIN_WORDS_ROOM pad1
#define TP_BIN_WORDS_FIRST pad2
// Set in TP_BIN_WORDS_SCALE: a word per candidate instead of a bit, scale * (TP_BIN_WORDS_ADD
// + counts[t]) words a tile (the transparent lists as light indices: HybridBlended).
#define TP_BIN_WORDS_INDICES 0x80000000u

// The rectangles step: 1 when it stores the rectangles for the fill (the frame), 0 when it
// only counts them (the plan-time sizing, which has no rectangle buffer).
#define TP_BIN_STORE_RECTS materialIndex
// The fill: how many workgroups share each 64 lights' (light, tile) pairs.
#define TP_BIN_SPLIT materialIndex
// The fill's split is chosen so that at least this many workgroups run (or one per 64 lights),
// each 64 lights' pairs over at most TP_BIN_FILL_SPLIT_MAX of them: on a GPU enough to fill it
// with waits on atomics (H200, 1,024 lights of the default range: light_bin_fill 0.69 ms with a
// workgroup per 64 lights; at 65,536 lights 0.117 ms with 2,048 workgroups, 0.100 with 4,096,
// 0.092 with 8,192, 0.087 with 16,384, 0.086 with 24,576), but not so thinly that a workgroup
// has little to walk (1,024 lights: 0.030 ms with 512 workgroups a 64 lights, 0.031 with 1,024;
// docs/clustered.md); on a CPU device a few, each workgroup's scan costing barriers there.
#define TP_BIN_FILL_GROUPS_GPU 16384u
#define TP_BIN_FILL_GROUPS_CPU 8u
#define TP_BIN_FILL_SPLIT_MAX 512u
// Shared memory the fill's workgroup reserves and does not need (a specialization constant,
// in words): on the H200, with many lights a tile, a 64-lane workgroup holding 4 KiB more fills
// faster (1,000,000 lights: light_bin_fill 0.219 -> 0.184 ms; reserving 1 KiB 0.208, 8 KiB
// 0.178), with fewer it does not (65,536 lights: 0.091 -> 0.090; 1,024: 0.030 -> 0.032). Fewer workgroups
// share a multiprocessor, or its split between L1 and shared memory moves: which of the two
// was not measured (docs/clustered.md). Reserved on a GPU from TP_BIN_FILL_RESERVE_PER_TILE
// lights a tile.
#define TP_BIN_SPEC_FILL_RESERVE 14
#define TP_BIN_FILL_RESERVE_WORDS 1024u
#define TP_BIN_FILL_RESERVE_PER_TILE 32u

// Runs up to this long are sorted in shared memory (16 KiB of lavapipe's 32, and 3 KiB of
// buckets and scan); longer ones by blocks of this size: the bitonic steps within a block in
// shared memory (bin_sort_local.comp), a dispatch per step only across blocks
// (bin_sort_step.comp).
#define TP_BIN_SHARED_SORT 4096u
// bin_sort.comp's run in shared memory, sized to the frame's longest planned run (a
// specialization constant: the power of two at or above GpuBinning::runBound, at most
// TP_BIN_SHARED_SORT, at least TP_BIN_SORT_SHARED_LEAST): 16 KiB a workgroup held fewer of them
// on a multiprocessor than the sort could use (H200, 1920x1080: light_bin_sort 0.103 -> 0.061
// ms at 65,536 lights, runs of up to 1,274 in 2,048 words; 0.078 -> 0.032 at 1,024 lights, 512
// words; docs/clustered.md).
#define TP_BIN_SPEC_SORT_SHARED 15
#define TP_BIN_SORT_SHARED_LEAST 256u
// Invocations sorting one tile's run (bin_sort.comp's workgroup size, a specialization
// constant): 256 on a GPU, where the short runs' sort by rank and each bitonic step then take
// one or two elements a lane (H100, 1920x1080: light_bin_sort 0.35 -> 0.17 ms at 65,536
// lights, 0.55 -> 0.23 ms at 1,000,000, against 64; 512 was level, 1024 slower); 64 on a CPU
// device, where a workgroup runs as 8-lane coroutines switching at every barrier.
#define TP_BIN_SPEC_SORT_GROUP 12
#define TP_BIN_SORT_GROUP_GPU 256u
#define TP_BIN_SORT_GROUP_CPU 64u
#define TP_BIN_RANK_SORT 128u      // runs up to this long: each light to its rank (one barrier)
// Longer runs in shared memory by buckets over the range of every local light's index
// (bin_sort.comp): how many (a power of two; a specialization constant, so that tests can
// crowd them), and the most lights a bucket may hold before the run is sorted by the bitonic
// network instead (each of a bucket's lights compares with all of them). H200, 1920x1080
// (docs/clustered.md): 256 buckets and ranks up to 128 lights beat 64, 128 and 512 buckets and
// ranks up to 64, 256 and 512.
#define TP_BIN_SPEC_SORT_BUCKETS 13
#define TP_BIN_SORT_BUCKETS 256u
#define TP_BIN_BUCKET_MOST 64u
#define TP_BIN_STEP_PAIRS 64u      // long-run step: pairs per invocation and dispatch
// Tiles one fill dispatch may visit per light: lavapipe ends an invocation after 65,535
// loop iterations in total (core/passes/tiled_lighting.h); the slab loops add tilesX + tilesY.
#define TP_BIN_FILL_BUDGET 32768u

// The padding of the light's sphere: far more than the GPU culling test's (relative 1e-4),
// so float rounding there can never make it keep a light a rectangle excludes. Powers of two
// (exact in float, in C++ and GLSL literals alike); the distance term takes the L1 norm,
// an upper bound of the length that needs no square root (not correctly rounded in Vulkan).
#define TP_BIN_RANGE_SCALE 1.0009765625f // 1 + 2^-10
#define TP_BIN_DISTANCE_PAD 0.0009765625f // 2^-10 per unit of |x| + |y| + |z|
#define TP_BIN_ABSOLUTE_PAD 0.0001220703125f // 2^-13

TP_STRUCT(BinInputs) {
    uvec4 grid;  // tilesX, tilesY, tiles, local lights
    uvec4 slabs; // first slab of: column lo, column hi, row lo, row hi (in vec4 slabs[])
};

// The light's centre in view space: column-major view times (p, 1), spelled out.
TP_INLINE vec3 binViewCentre(mat4 v, vec3 p) {
    TP_PRECISE float x = ((v[0][0] * p.x + v[1][0] * p.y) + v[2][0] * p.z) + v[3][0];
    TP_PRECISE float y = ((v[0][1] * p.x + v[1][1] * p.y) + v[2][1] * p.z) + v[3][1];
    TP_PRECISE float z = ((v[0][2] * p.x + v[1][2] * p.y) + v[2][2] * p.z) + v[3][2];
    return vec3(x, y, z);
}

TP_INLINE float binPaddedRadius(float range, vec3 c) {
    TP_PRECISE float l1 = (max(c.x, -c.x) + max(c.y, -c.y)) + max(c.z, -c.z);
    TP_PRECISE float r = (range * TP_BIN_RANGE_SCALE + l1 * TP_BIN_DISTANCE_PAD) + TP_BIN_ABSOLUTE_PAD;
    return r;
}

// The whole padded sphere lies behind the eye (view space looks down -z).
TP_INLINE bool binBehindEye(vec3 c, float r) {
    TP_PRECISE float nearest = c.z - r;
    return nearest > 0.0f;
}

// The whole padded sphere lies in front of the eye: the slab planes' half-spaces are nested
// there, so the slab ranges are found by bisection (tile_bound.cpp: slabRange).
TP_INLINE bool binInFront(vec3 c, float r) {
    TP_PRECISE float farthest = c.z + r;
    return farthest < 0.0f;
}

// plane: unit inward normal (xyz) and offset (w). True when the padded sphere lies wholly outside.
TP_INLINE bool binOutside(vec4 plane, vec3 c, float r) {
    TP_PRECISE float d = ((plane.x * c.x + plane.y * c.y) + plane.z * c.z) + plane.w;
    return d < -r;
}

// A tile rectangle in two words, (x0 | x1 << 16, y0 | y1 << 16): a grid is at most 65,535
// tiles a side (maxImageDimension2D / the smallest tile). Empty: x0 > x1, as binRect gives it.
TP_INLINE uvec2 binPackRect(ivec4 rect) {
    if (rect.x > rect.y || rect.z > rect.w) return uvec2(1u, 0u);
    return uvec2(uint(rect.x) | (uint(rect.y) << 16u), uint(rect.z) | (uint(rect.w) << 16u));
}
TP_INLINE ivec4 binUnpackRect(uvec2 p) {
    return ivec4(int(p.x & 0xffffu), int(p.x >> 16u), int(p.y & 0xffffu), int(p.y >> 16u));
}

#ifndef TP_GLSL
static_assert(sizeof(BinInputs) == 32);
} // namespace tp::gpu
#endif
#endif
