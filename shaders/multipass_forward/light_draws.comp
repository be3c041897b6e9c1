#version 460
#extension GL_GOOGLE_include_directive : require
// Multipass forward's per-light draw lists on the GPU (multipass_forward/light_draw_pass.h): one
// invocation per local light walks the opaque then masked draws in the scene's order and writes
// an indexed indirect draw for each one its light touches (the light plan's rules:
// mpRectsOverlap, and mpSphereTouchesBox at 1x) into its own region, compacted per run of one
// cull mode, in draw order; then the run counts and the light's mesh count. The order is the
// CPU plan's, so the light passes draw each light's meshes in the same order as before.
#include "include/shared.h"
#include "multipass_forward/light_draws.h"

layout(local_size_x = TP_MPLD_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_PARAMS) readonly buffer ParamsBlock {
    LightDrawParams params;
};
layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_LIGHTS) readonly buffer LightBlock {
    LightDrawLight lightRows[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_DRAWS) readonly buffer DrawBlock {
    LightDrawDraw drawRows[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_COMMANDS) writeonly buffer CommandBlock {
    uint commands[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_COUNTS) writeonly buffer CountBlock {
    uint counts[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_MESHES) writeonly buffer MeshBlock {
    uint meshes[];
};

void main() {
    const uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.lightCount || params.drawCount == 0u) return;
    const LightDrawLight l = lightRows[slot];
    const uint region = slot * params.drawCount, countBase = slot * params.runCount;
    uint run = 0u, n = 0u, total = 0u;
    for (uint i = 0u; i < params.drawCount; ++i) { // an explicit count (docs: LAVAPIPE.md)
        const LightDrawDraw d = drawRows[i];
        if (d.run != run) {
            counts[countBase + run] = n;
            run = d.run;
            n = 0u;
        }
        if (!mpLightTouchesDraw(l, d, params.boxTest != 0u)) continue;
        const uint w = (region + d.runFirst + n) * TP_MPLD_COMMAND_WORDS;
        commands[w + 0u] = d.indexCount;
        commands[w + 1u] = 1u;
        commands[w + 2u] = d.firstIndex;
        commands[w + 3u] = uint(d.vertexOffset);
        commands[w + 4u] = d.material; // firstInstance: the material (scene_material_vert)
        ++n;
        ++total;
    }
    counts[countBase + run] = n;
    meshes[slot] = total;
}
