#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 2: per point/spot light, its conservative tile rectangle - the same
// test, in the same float operations, as la::conservativeTileRects (include/light_binning.h)
// - and its four corners in the tiles' difference array (integer atomics: the counts do not
// depend on the order). Corners past the last column or row are left out: they would only
// change sums outside the grid.
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

// First and last slab the sphere meets (first > last: none); every slab is tested.
ivec2 slabRange(uint loFirst, uint hiFirst, uint count, vec3 c, float r) {
    ivec2 range = ivec2(int(count), -1);
    for (uint i = 0u; i < count; ++i) {
        if (binOutside(slabs[loFirst + i], c, r)) continue;
        if (binOutside(slabs[hiFirst + i], c, r)) continue;
        range.x = min(range.x, int(i));
        range.y = int(i);
    }
    return range;
}

void main() {
    const uint k = binFlatIndex();
    if (k >= bin.grid.w) return;
    const LightGpu l = lights[locals[k]];
    const vec3 c = binViewCentre(frame.view, l.position);
    const float r = binPaddedRadius(l.range, c);
    ivec4 rect = ivec4(int(bin.grid.x), -1, int(bin.grid.y), -1);
    if (!binBehindEye(c, r)) {
        rect.xy = slabRange(bin.slabs.x, bin.slabs.y, bin.grid.x, c, r);
        if (rect.x <= rect.y) rect.zw = slabRange(bin.slabs.z, bin.slabs.w, bin.grid.y, c, r);
    }
    rects[k] = rect;
    if (rect.x > rect.y || rect.z > rect.w) return;
    const uint W = bin.grid.x, H = bin.grid.y;
    const uint x0 = uint(rect.x), x1 = uint(rect.y) + 1u, y0 = uint(rect.z), y1 = uint(rect.w) + 1u;
    atomicAdd(counts[y0 * W + x0], 1u);
    if (x1 < W) atomicAdd(counts[y0 * W + x1], 0xffffffffu); // -1, modulo 2^32
    if (y1 < H) atomicAdd(counts[y1 * W + x0], 0xffffffffu);
    if (x1 < W && y1 < H) atomicAdd(counts[y1 * W + x1], 1u);
}
