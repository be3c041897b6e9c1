#version 460
#extension GL_GOOGLE_include_directive : require
// light_bin_fill (step 5): every light into the runs of the tiles its rectangle covers, rows
// [TP_BIN_FIRST, TP_BIN_END) of tiles per dispatch (lavapipe's loop limit: at most
// TP_BIN_FILL_BUDGET tiles per light and dispatch). Each tile's count, counted down
// (atomic), is its cursor: the order inside a run depends on scheduling until the sort.
// The first TP_BIN_SMALL_GROUPS workgroups take an invocation per light and fill the small
// rectangles (at most TP_BIN_BIG_RECT tiles, a short loop); each workgroup after those takes
// one light of the big list and spreads its tiles over its invocations, so that no
// invocation walks a rectangle over much of the screen alone.
#include "lightassign/bin_common.glsl"

layout(local_size_x = 64) in;

// Rows [y0, y1) of the rectangle that this dispatch fills.
uvec2 binRows(ivec4 rect) {
    return uvec2(max(uint(rect.z), draw.TP_BIN_FIRST), min(uint(rect.w) + 1u, draw.TP_BIN_END));
}

void fillSmall(uint index) {
    if (index >= bin.grid.w) return;
    // Lights in descending order: a device that happens to run the workgroups in order (as
    // lavapipe nearly does) would leave the runs ascending and hide a broken sort from the tests.
    const uint k = bin.grid.w - 1u - index;
    const ivec4 rect = binRect(k); // what the rectangles step counted, computed again
    const uint area = binRectArea(rect);
    if (area == 0u || area > TP_BIN_BIG_RECT) return;
    const uint W = bin.grid.x, light = locals[k];
    const uvec2 rows = binRows(rect);
    for (uint y = rows.x; y < rows.y; ++y)
        for (uint x = uint(rect.x); x <= uint(rect.y); ++x) binFillTile(y * W + x, light);
}

void fillBig(uint b) {
    if (b >= bigCount) return; // uniform over the workgroup
    const uint k = bigLights[b];
    const ivec4 rect = binRect(k);
    const uvec2 rows = binRows(rect);
    if (rows.x >= rows.y) return;
    const uint W = bin.grid.x, light = locals[k], width = uint(rect.y - rect.x + 1);
    // Tile i of the rectangle's rows is (i / width, i % width); stepping i by 64 steps that
    // by (64 / width, 64 % width) with a carry: no division per tile.
    const uint lane = gl_LocalInvocationIndex, stepRows = 64u / width, stepCols = 64u % width;
    uint y = rows.x + lane / width, x = lane % width;
    for (; y < rows.y; y += stepRows) {
        binFillTile(y * W + uint(rect.x) + x, light);
        x += stepCols;
        if (x >= width) {
            x -= width;
            ++y;
        }
    }
}

void main() {
    const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    if (group < draw.TP_BIN_SMALL_GROUPS) fillSmall(group * 64u + gl_LocalInvocationIndex);
    else fillBig(group - draw.TP_BIN_SMALL_GROUPS);
}
