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
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_RECTS) buffer BinRectBlock {
    ivec4 rects[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_COUNTS) buffer BinCountBlock {
    uint counts[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_OFFSETS) buffer BinOffsetBlock {
    uint offsets[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_CURSORS) buffer BinCursorBlock {
    uint cursors[];
};
layout(std430, set = TP_SET_PASS, binding = TP_BIN_BINDING_TARGET) buffer BinTargetBlock {
    uint target[];
};

// A flat index (light or tile): 64 invocations per workgroup, workgroups in a 2D grid (a dispatch
// dimension holds at most 65,535).
uint binFlatIndex() {
    return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
}

// Sums that would pass 2^32 - 1 stay there: the CPU clamps its offsets the same way (and
// refuses such a layout before any frame).
uint binSaturatingAdd(uint a, uint b) {
    return a > 0xffffffffu - b ? 0xffffffffu : a + b;
}

// The padded power of two a run of n sorts as.
uint binSortSize(uint n) {
    return n <= 1u ? 1u : 1u << uint(findMSB(n - 1u) + 1);
}
#endif
