#version 460
#extension GL_GOOGLE_include_directive : require
// The shadow maps' compute rasterizer's second pass (pass "shadow_raster_big", core/passes/
// shadow_raster.h): one workgroup per triangle shadow_raster listed, dispatched indirectly
// with the count it wrote (at most 65,535 groups, each taking every so-many-th triangle past
// that). The group sets the triangle up again on its face (the same clipping and snapping, so
// the same polygon) and its invocations share the texels of each fan triangle's bounds. Then
// the meshlets of the triangles the full list could not take: their large triangles again.
#include "shadow/shadow_raster.glsl"

layout(local_size_x = TP_RT_BIG_GROUP) in;

// Triangle t of a meshlet whose triangles overflowed the list, if it is large (all of them
// again: those that were listed too change nothing, the atomic max being idempotent). One
// triangle per item, not a meshlet's loop: lavapipe ends an invocation after 65,535 loop
// iterations (docs/shading.md), and a meshlet's large triangles would pass that.
uint rasterOverflowed(uint slot, uint t, uint lane) {
    uint i0, i1, i2, r;
    if (!slotTriangle(slot, t, i0, i1, i2, r)) return 0u; // the same for the whole group
    ShadowCullRow row = rows[r];
    bool masked = (row.flags & TP_SR_FLAG_MASKED) != 0u;
    useFace(row.face, masked);
    RasterVertex v0, v1, v2;
    bool clipped, drew;
    if (rasterTriage(clipPosition(i0), clipPosition(i1), clipPosition(i2), true, clipped, v0, v1,
                     v2) != TP_RT_LIST)
        return 0u;
    return rasterListed(i0, i1, i2, r, true, masked, row.material, true, lane, drew);
}

void main() {
    uint atomics = 0u;
    uint capacity = (uint(list.length()) - TP_SR_LIST_HEADER) / 4u;
    uint listed = min(list[TP_SR_LIST_SLOTS], capacity);
    for (uint t = gl_WorkGroupID.x; t < listed; t += gl_NumWorkGroups.x) {
        uint at = TP_SR_LIST_HEADER + 4u * t;
        uint r = list[at + 3u];
        ShadowCullRow row = rows[r];
        bool masked = (row.flags & TP_SR_FLAG_MASKED) != 0u;
        useFace(row.face, masked);
        bool drew;
        atomics += rasterListed(list[at], list[at + 1u], list[at + 2u], r, true, masked,
                                row.material, true, gl_LocalInvocationIndex, drew);
    }
    uint items = list[TP_SR_OVERFLOW_MESHLETS] * TP_SR_GROUP; // (meshlet, triangle)
    for (uint m = gl_WorkGroupID.x; m < items; m += gl_NumWorkGroups.x)
        atomics += rasterOverflowed(overflowSlots[m / TP_SR_GROUP], m % TP_SR_GROUP,
                                    gl_LocalInvocationIndex);
    if (atomics != 0u) atomicAdd(list[TP_SR_ATOMICS_BIG], atomics); // the work counts
}
