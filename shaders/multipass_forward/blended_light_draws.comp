#version 460
#extension GL_GOOGLE_include_directive : require
// Multipass forward's blended draws' light lists on the GPU (multipass_forward/
// blended_light_draw_pass.h). Invocations [0, blendedCount): one per blended draw on screen, in
// the blended pass's back-to-front order, walks the local lights in light order and writes, for
// each light that touches the draw (the light plan's rule, mpLightTouchesDraw), the light's draw
// of the draw's reversed triangles and then its transmittance reset, as two indexed indirect
// draws whose firstInstance names the light's slot (TP_MPBL_RESET on the reset); then its count.
// Invocations [blendedCount, blendedCount + lightCount): one per light, the blended draws it
// lights (the counters' meshes per light), so nothing needs an atomic or a cleared buffer.
#include "include/shared.h"
#include "multipass_forward/blended_light_draws.h"

layout(local_size_x = TP_MPBL_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_MPBL_BINDING_PARAMS) readonly buffer ParamsBlock {
    BlendedLightDrawParams params;
};
layout(std430, set = TP_SET_PASS, binding = TP_MPBL_BINDING_LIGHTS) readonly buffer LightBlock {
    LightDrawLight lightRows[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPBL_BINDING_DRAWS) readonly buffer DrawBlock {
    LightDrawDraw drawRows[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPBL_BINDING_COMMANDS) writeonly buffer CommandBlock {
    uint commands[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPBL_BINDING_COUNTS) writeonly buffer CountBlock {
    uint counts[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPBL_BINDING_MESHES) writeonly buffer MeshBlock {
    uint meshes[];
};

void writeCommand(uint command, LightDrawDraw d, uint word) {
    const uint w = command * TP_MPLD_COMMAND_WORDS;
    commands[w + 0u] = d.indexCount;
    commands[w + 1u] = 1u;
    commands[w + 2u] = d.firstIndex; // in the reversed index buffer (blended_pass.cpp)
    commands[w + 3u] = uint(d.vertexOffset);
    commands[w + 4u] = word; // firstInstance: the light's slot, and whether it is the reset
}

void main() {
    const uint id = gl_GlobalInvocationID.x;
    const bool boxTest = params.boxTest != 0u;
    if (id < params.blendedCount) {
        const LightDrawDraw d = drawRows[id];
        const uint region = id * 2u * params.lightCount;
        uint n = 0u;
        for (uint s = 0u; s < params.lightCount; ++s) { // an explicit count (LAVAPIPE.md)
            if (!mpLightTouchesDraw(lightRows[s], d, boxTest)) continue;
            writeCommand(region + n, d, s);
            writeCommand(region + n + 1u, d, s | TP_MPBL_RESET);
            n += 2u;
        }
        counts[id] = n;
        return;
    }
    const uint slot = id - params.blendedCount;
    if (slot >= params.lightCount) return;
    const LightDrawLight l = lightRows[slot];
    uint lit = 0u;
    for (uint b = 0u; b < params.blendedCount; ++b)
        if (mpLightTouchesDraw(l, drawRows[b], boxTest)) ++lit;
    meshes[slot] = lit;
}
