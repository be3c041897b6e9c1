#version 460
#extension GL_GOOGLE_include_directive : require
// The shadow maps' compute rasterizer's first pass (pass "shadow_raster", core/passes/
// shadow_raster.h): one workgroup per TP_SR_SLOTS_PER_GROUP command slots of shadow_cull (a
// meshlet of a (face, draw) row each, if the cull kept that many), one invocation per triangle
// of each kept meshlet in turn. A triangle whose texel
// bounds fit in TP_RT_SMALL_PIXELS each way is rasterized here by its own invocation; a larger
// one, or one the near plane or the face's guard band cuts, is listed for shadow_raster_big.
// A triangle the full list cannot take is counted (TP_SR_OVERFLOW) and its meshlet listed in the
// overflow buffer, whose large triangles shadow_raster_big rasterizes again: none is dropped.
#include "shadow/shadow_raster.glsl"

layout(local_size_x = TP_SR_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_ARGS) buffer ArgsBlock {
    uint args[];
};

shared uint sCounts[TP_SR_COUNTERS];
shared uint sAtomics, sOverflow;

// Lists the triangle for shadow_raster_big; false when the list is full (its slots counted
// all the same, so the overflow shows: the group lists its meshlet instead).
bool listTriangle(uint i0, uint i1, uint i2, uint row) {
    uint slot = atomicAdd(list[TP_SR_LIST_SLOTS], 1u);
    uint capacity = (uint(list.length()) - TP_SR_LIST_HEADER) / 4u;
    if (slot >= capacity) return false;
    atomicMax(args[0], min(slot + 1u, 65535u));
    uint at = TP_SR_LIST_HEADER + 4u * slot;
    list[at] = i0;
    list[at + 1u] = i1;
    list[at + 2u] = i2;
    list[at + 3u] = row;
    return true;
}

// One triangle: TP_SR_COUNT_SMALL, _BIG or _CULLED; `atomics`: the atomics it issued here.
uint triangleOutcome(uint i0, uint i1, uint i2, uint row, bool masked, uint material,
                     out bool clipped, out bool overflow, out uint atomics) {
    atomics = 0u;
    overflow = false;
    RasterVertex v0, v1, v2;
    uint triage = rasterTriage(clipPosition(i0), clipPosition(i1), clipPosition(i2), true,
                               clipped, v0, v1, v2);
    if (triage == TP_RT_CULLED) return TP_SR_COUNT_CULLED;
    if (triage == TP_RT_LIST) {
        overflow = !listTriangle(i0, i1, i2, row);
        return TP_SR_COUNT_BIG;
    }
    bool drew;
    atomics = rasterTriangleAs(v0, v1, v2, i0, i1, i2, row, true, masked, material, false, 0u,
                               drew);
    return drew ? TP_SR_COUNT_SMALL : TP_SR_COUNT_CULLED;
}

// Command slot `slot` of row r, kept: one triangle per invocation, its outcome counted in the
// group's shared counters; then the meshlet listed once if the full list refused a triangle.
void rasterSlot(uint slot, uint r, uint lane) {
    uint i0, i1, i2;
    if (commandTriangle(slot, lane, i0, i1, i2)) {
        ShadowCullRow row = rows[r];
        bool masked = (row.flags & TP_SR_FLAG_MASKED) != 0u;
        useFace(row.face, masked);
        bool clipped, overflow;
        uint atomics;
        atomicAdd(sCounts[triangleOutcome(i0, i1, i2, r, masked, row.material, clipped,
                                          overflow, atomics)], 1u);
        if (clipped) atomicAdd(sCounts[TP_SR_COUNT_CLIPPED], 1u);
        if (overflow) atomicAdd(sOverflow, 1u);
        if (atomics != 0u) atomicAdd(sAtomics, atomics);
    }
    barrier();
    if (lane == 0u && sOverflow != 0u) {
        // The meshlet once, for shadow_raster_big's groups to rasterize its large triangles.
        atomicAdd(list[TP_SR_OVERFLOW], sOverflow);
        uint at = atomicAdd(list[TP_SR_OVERFLOW_MESHLETS], 1u);
        overflowSlots[at] = slot;
        atomicMax(args[0], min((at + 1u) * TP_SR_GROUP, 65535u)); // a group per triangle
        sOverflow = 0u;
    }
    barrier();
}

// A group takes TP_SR_SLOTS_PER_GROUP consecutive command slots (most of them empty: a row's
// kept meshlets are compacted at the start of its range) and walks them a row at a time, past
// each row's empty rest: one bisection for the row of its first slot, not one per slot, and a
// group launched for every so-many slots rather than every one. Every branch and loop below is
// the whole group's (the same slot, row and counts for every invocation).
void main() {
    uint lane = gl_LocalInvocationIndex;
    if (lane < TP_SR_COUNTERS) sCounts[lane] = 0u;
    if (lane == 0u) {
        sAtomics = 0u;
        sOverflow = 0u;
    }
    barrier();
    uint group = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
    uint slots = uint(commands.length()) / 5u, rowCount = uint(rows.length());
    uint slot = group * TP_SR_SLOTS_PER_GROUP;
    uint end = min(slot + TP_SR_SLOTS_PER_GROUP, slots);
    uint r = slot < end ? rowOfCommand(slot) : 0u;
    while (slot < end) {
        while (r + 1u < rowCount && rows[r + 1u].firstCommand <= slot) ++r;
        if (!slotKept(slot, r)) { // the rest of the row's range is empty too
            slot = r + 1u < rowCount ? rows[r + 1u].firstCommand : end;
            continue;
        }
        rasterSlot(slot, r, lane);
        ++slot;
    }
    barrier();
    if (lane < TP_SR_COUNTERS && sCounts[lane] != 0u) atomicAdd(list[lane], sCounts[lane]);
    if (lane == 0u && sAtomics != 0u) atomicAdd(list[TP_SR_ATOMICS_SMALL], sAtomics);
}
