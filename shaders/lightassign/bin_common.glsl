// The light_binning pass's set (include/light_binning.h); GLSL only. Each step of the pass
// is one shader of this folder; all share this one set.
#ifndef TP_BIN_COMMON_GLSL
#define TP_BIN_COMMON_GLSL
#include "include/shared.h"
#include "include/light_binning.h"
#include "include/scene_bindings.glsl"

layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_INPUTS) readonly buffer BinInputBlock {
    BinInputs bin;
    vec4 slabs[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_LOCALS) readonly buffer BinLocalBlock {
    uint locals[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_COUNTS) buffer BinCountBlock {
    uint counts[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_OFFSETS) buffer BinOffsetBlock {
    uint offsets[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_ROWS) buffer BinRowBlock {
    uint rowSums[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_TARGET) buffer BinTargetBlock {
    uint target[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_RECTS) buffer BinRectBlock {
    uvec2 rects[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_WORDS) buffer BinWordBlock {
    uint words[];
};

// A flat index (light or tile): 64 invocations per workgroup, workgroups in a 2D grid (a dispatch
// dimension holds at most 65,535).
uint binFlatIndex() {
    return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
}

// First and last slab the sphere meets (first > last: none): la::conservativeTileRects's
// slabRange (tile_bound.cpp), the same probes in the same order - bisection when the sphere
// lies wholly in front of the eye (the half-spaces are nested there), else every slab.
ivec2 binSlabRange(uint loFirst, uint hiFirst, uint count, bool flip, vec3 c, float r) {
    ivec2 range = ivec2(int(count), -1);
    if (binInFront(c, r)) {
        const uint before = flip ? loFirst : hiFirst, after = flip ? hiFirst : loFirst;
        uint lo = 0u, hi = count; // the first slab that `before` does not exclude
        while (lo < hi) {
            const uint mid = (lo + hi) / 2u;
            if (binOutside(slabs[before + mid], c, r)) lo = mid + 1u;
            else hi = mid;
        }
        const uint begin = lo;
        hi = count; // the first slab from `begin` on that `after` excludes
        while (lo < hi) {
            const uint mid = (lo + hi) / 2u;
            if (binOutside(slabs[after + mid], c, r)) hi = mid;
            else lo = mid + 1u;
        }
        if (begin < lo) range = ivec2(int(begin), int(lo) - 1);
        return range;
    }
    for (uint i = 0u; i < count; ++i) {
        if (binOutside(slabs[loFirst + i], c, r)) continue;
        if (binOutside(slabs[hiFirst + i], c, r)) continue;
        range.x = min(range.x, int(i));
        range.y = int(i);
    }
    return range;
}

// Light k's conservative tile rectangle (x0, x1, y0, y1; empty when x0 > x1 or y0 > y1):
// la::conservativeTileRects's test, the same float operations (include/light_binning.h).
// The rectangles step computes it once and stores it packed (8 bytes a light) for the fill:
// computing it again there (the bisection, and the light's 64 bytes read again) took
// 0.07 ms of the fill's 0.15 at 65,536 lights on the H200 (docs/clustered.md).
ivec4 binRect(uint k) {
    const LightGpu l = lights[locals[k]];
    const vec3 c = binViewCentre(frame.view, l.position);
    const float r = binPaddedRadius(l.range, c);
    ivec4 rect = ivec4(int(bin.grid.x), -1, int(bin.grid.y), -1);
    if (binBehindEye(c, r)) return rect;
    rect.xy = binSlabRange(bin.slabs.x, bin.slabs.y, bin.grid.x, false, c, r);
    if (rect.x <= rect.y) rect.zw = binSlabRange(bin.slabs.z, bin.slabs.w, bin.grid.y, true, c, r);
    return rect;
}

// Tiles a rectangle covers (0 when empty).
uint binRectArea(ivec4 rect) {
    return rect.x > rect.y || rect.z > rect.w ? 0u : uint(rect.y - rect.x + 1) * uint(rect.w - rect.z + 1);
}

// Light `light`'s slot in tile t's run: the tile's count, counted down (atomic: scheduling
// order until the sort), is the cursor.
// A view past the planned room has its offsets clamped (bin_scan_columns.comp): a slot past
// the tile's clamped run is not written (counted there, not here).
void binFillTile(uint t, uint light) {
    const uint slot = offsets[t] + atomicAdd(counts[t], 0xffffffffu) - 1u;
    if (slot < offsets[t + 1u]) target[draw.TP_BIN_BASE + slot] = light;
}

// The padded power of two a run of n sorts as.
uint binSortSize(uint n) {
    return n <= 1u ? 1u : 1u << uint(findMSB(n - 1u) + 1);
}

// Bitonic sort, pair p of the step with block size k and distance j (powers of two): its
// lower index and its partner, in the formulation whose comparators all put the smaller value
// first (a merge's first step pairs i with its mirror in the block), so +inf padding stays
// at the end. Used by the three sort shaders (shared memory, blocks, steps across blocks).
// i = (p / j) * 2j + p % j, without dividing.
uvec2 binBitonicPair(uint p, uint k, uint j) {
    const uint i = ((p & ~(j - 1u)) << 1u) | (p & (j - 1u));
    return uvec2(i, j == k >> 1u ? i ^ (k - 1u) : i + j);
}
#endif
