#version 460
#extension GL_GOOGLE_include_directive : require
// The compute rasterizer's second pass (pass "vis_raster_big", compute mode): one workgroup per
// triangle vis_raster listed (too large for one invocation), dispatched indirectly with the
// count it wrote (at most 65,535 groups, each taking every so-many-th triangle past that). The group sets the triangle up again (the same clipping and snapping, so the
// same polygon) and its invocations share the pixels of each fan triangle's bounds.
#include "visbuffer/vis_raster.glsl"

layout(local_size_x = TP_VR_BIG_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_LIST) buffer ListBlock {
    uint list[];
};

void main() {
    uint atomics = 0u;
    for (uint t = gl_WorkGroupID.x; t < list[TP_VR_LIST_SLOTS]; t += gl_NumWorkGroups.x) {
        uint at = TP_VR_LIST_HEADER + 4u * t;
        atomics += rasterListedTriangle(list[at], list[at + 1u], list[at + 2u], list[at + 3u],
                                        gl_LocalInvocationIndex);
    }
    if (atomics != 0u) atomicAdd(list[TP_VR_ATOMICS_BIG], atomics); // the work counts
}
