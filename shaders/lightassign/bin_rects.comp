#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 2: per point/spot light, its conservative tile rectangle - the same
// test, in the same float operations, as la::conservativeTileRects (include/light_binning.h)
// - and its four corners in the tiles' difference array (integer atomics: the counts do not
// depend on the order). Corners past the last column or row are left out: they would only
// change sums outside the grid. In the frame it also stores the rectangle for the fill.
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

void main() {
    const uint k = binFlatIndex();
    if (k >= bin.grid.w) return;
    const ivec4 rect = binRect(k);
    if (draw.TP_BIN_STORE_RECTS != 0u) rects[k] = binPackRect(rect);
    if (rect.x > rect.y || rect.z > rect.w) return;
    const uint W = bin.grid.x, H = bin.grid.y;
    const uint x0 = uint(rect.x), x1 = uint(rect.y) + 1u, y0 = uint(rect.z), y1 = uint(rect.w) + 1u;
    atomicAdd(counts[y0 * W + x0], 1u);
    if (x1 < W) atomicAdd(counts[y0 * W + x1], 0xffffffffu); // -1, modulo 2^32
    if (y1 < H) atomicAdd(counts[y1 * W + x0], 0xffffffffu);
    if (x1 < W && y1 < H) atomicAdd(counts[y1 * W + x1], 1u);
}
