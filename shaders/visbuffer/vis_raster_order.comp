#version 460
#extension GL_GOOGLE_include_directive : require
// Hybrid mode (--vis-raster hybrid), pass "vis_raster_order": the triangles vis_raster staged
// per chunk (vis_raster.h) packed into the hardware's list, chunk after chunk and each chunk's
// in lane order: the order of the draws' triangles, whatever order vis_raster's workgroups ran
// in. The hardware's depth test keeps the first of two equal depths and its early test rejects
// by what was drawn before, so a list in arrival order made the ids of ties and the fragment
// counts vary from run to run. A workgroup per chunk; its place is the sum of the counts before
// it (integer sums: the same in any order). The last chunk writes the draw's vertex count.
#include "include/shared.h"
#include "visbuffer/vis_raster.h"

layout(local_size_x = TP_VR_GROUP) in;
layout(constant_id = TP_VR_SPEC_CHUNKS) const uint kChunks = 1u;

layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_ORDER_STAGED) readonly buffer StagedBlock {
    uint staged[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_ORDER_LIST) writeonly buffer ListBlock {
    uint list[];
};
layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_ORDER_ARGS) writeonly buffer ArgsBlock {
    uint args[];
};

shared uint sBefore;

void main() {
    const uint chunk = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
    const uint lane = gl_LocalInvocationIndex;
    if (chunk >= kChunks) return; // uniform over the workgroup
    if (lane == 0u) sBefore = 0u;
    barrier();
    uint before = 0u;
    for (uint c = lane; c < chunk; c += TP_VR_GROUP) before += staged[TP_VR_LIST_HEADER + c];
    if (before != 0u) atomicAdd(sBefore, before);
    barrier();
    const uint first = sBefore, count = staged[TP_VR_LIST_HEADER + chunk];
    if (lane < count) {
        const uint from = TP_VR_LIST_HEADER + kChunks + 4u * (chunk * TP_VR_GROUP + lane);
        const uint to = 4u * (first + lane);
        for (uint k = 0u; k < 4u; ++k) list[to + k] = staged[from + k];
    }
    if (chunk == kChunks - 1u && lane == 0u) args[0] = 3u * (first + count);
}
