#version 460
#extension GL_GOOGLE_include_directive : require
// light_binning, step 2: per point/spot light, its conservative tile rectangle - the same
// test, in the same float operations, as la::conservativeTileRects (include/light_binning.h)
// - and its four corners in the tiles' difference array (integer atomics: the counts do not
// depend on the order). Corners past the last column or row are left out: they would only
// change sums outside the grid. A rectangle of fewer tiles than it has corners inside the grid
// (1x1, 1x2, 1x3 and their transposes away from the last column and row; at that edge, with
// fewer corners, a 1x1) adds 1 to each of its tiles in the direct counts instead (the second
// half of the counts; bin_scan_rows.comp folds them in): fewer atomics on scattered words, the
// pass's largest cost with many small lights (H200, 1,000,000 lights: light_binning 0.213 ->
// 0.164 ms, docs/clustered.md). In the frame it also stores the rectangle for the fill.
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

// A non-empty rectangle's four corners in the difference array (+1 at its first tile, -1 past
// its last column and past its last row, +1 past both), as tile indices; 0xffffffff for a
// corner past the last column or row: it would only change sums outside the grid. The order
// matches kBinCornerSigns.
uvec4 binRectCorners(ivec4 rect) {
    const uint W = bin.grid.x, H = bin.grid.y;
    const uint x0 = uint(rect.x), x1 = uint(rect.y) + 1u, y0 = uint(rect.z), y1 = uint(rect.w) + 1u;
    const uint none = 0xffffffffu;
    return uvec4(y0 * W + x0, x1 < W ? y0 * W + x1 : none, y1 < H ? y1 * W + x0 : none,
                 x1 < W && y1 < H ? y1 * W + x1 : none);
}
const uvec4 kBinCornerSigns = uvec4(1u, 0xffffffffu, 0xffffffffu, 1u); // -1 modulo 2^32

void main() {
    const uint k = binFlatIndex();
    if (k >= bin.grid.w) return;
    const ivec4 rect = binRect(k);
    if (draw.TP_BIN_STORE_RECTS != 0u) rects[k] = binPackRect(rect);
    if (rect.x > rect.y || rect.z > rect.w) return;
    const uvec4 corners = binRectCorners(rect);
    uint cornerCount = 0u;
    for (uint i = 0u; i < 4u; ++i) cornerCount += corners[i] != 0xffffffffu ? 1u : 0u;
    const uint area = binRectArea(rect);
    if (area < cornerCount) {
        const uint W = bin.grid.x, direct = bin.grid.z;
        for (int y = rect.z; y <= rect.w; ++y)
            for (int x = rect.x; x <= rect.y; ++x) atomicAdd(counts[direct + uint(y) * W + uint(x)], 1u);
        return;
    }
    for (uint i = 0u; i < 4u; ++i)
        if (corners[i] != 0xffffffffu) atomicAdd(counts[corners[i]], kBinCornerSigns[i]);
}
