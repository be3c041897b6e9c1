#version 460
#extension GL_GOOGLE_include_directive : require
// Multipass forward's per-light draw lists on the GPU (multipass_forward/light_draw_pass.h): one
// invocation per local light walks the opaque then masked draws in the scene's order and writes
// an indexed indirect draw for each one its light touches (the light plan's rules:
// mpRectsOverlap, and mpSphereTouchesBox at 1x) into its own region, compacted per run of one
// cull mode, in draw order; then the run counts and the light's mesh count. The order is the
// CPU plan's, so the light passes draw each light's meshes in the same order as before.
//
// A draw's commands draw not the whole mesh but the runs of its meshlets whose bounding sphere
// the light's sphere reaches (consecutive in the meshlet index buffer, which holds each draw's
// meshlets side by side, in order), at most spansPerDraw of them: the last one then reaches on
// over the gaps to the last meshlet reached. A triangle left out lies in a meshlet the light
// cannot reach, where evalLight gives exactly 0, so drawing it would add nothing. A mesh whose
// meshlets the light reaches none of gets no command. Under MSAA at pixel rate the pixel centre
// a fragment is shaded at may lie off its triangle (params.meshletReach 0), so there a meshlet
// is kept where its sphere's screen rectangle meets the light's scissor: outside it no fragment
// of the meshlet is shaded at all. On lavapipe the light passes' time is the shading and
// geometry of what each light's draws cover, drawn again for every light; on the H200 their
// triangle setup, on the 4 SMs that rasterize.
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#include "include/meshlets.h"
#include "multipass_forward/light_draws.h"

layout(local_size_x = TP_MPLD_GROUP) in;

layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_PARAMS) readonly buffer ParamsBlock {
    LightDrawParams params;
};
layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_LIGHTS) readonly buffer LightRowBlock {
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
    uvec2 meshes[];
};
layout(std430, set = TP_SET_PASS, binding = TP_MPLD_BINDING_MESHLETS) readonly buffer MeshletBlock {
    MeshletGpu meshlets[];
};

// Command `at`: draw d's indices [first, end) of the meshlet index buffer. Returns its
// triangles.
uint writeCommand(uint at, LightDrawDraw d, uint first, uint end) {
    const uint w = at * TP_MPLD_COMMAND_WORDS;
    commands[w + 0u] = end - first;
    commands[w + 1u] = 1u;
    commands[w + 2u] = first;
    commands[w + 3u] = uint(d.vertexOffset);
    commands[w + 4u] = d.material; // firstInstance: the material (scene_material_vert)
    return (end - first) / 3u;
}

// Whether a fragment of a meshlet (camera-relative sphere) can lie in scissor `rect`: the
// pixels its sphere's screen rectangle touches (a pixel to spare, include/meshlets.h) meet it.
// A sphere that reaches the near plane, or anything not a number, may cover any pixel.
bool inScissor(vec3 centre, float radius, ivec4 rect) {
    const vec3 v = (frame.view * vec4(centre, 0.0)).xyz;
    const float r = radius + length(centre) * TP_MESHLET_ROTATION_EPS;
    if (!(sphereNearestDepth(v, r, frame.proj, frame.projParams.x) > 0.0)) return true;
    const vec4 s = sphereScreenRect(v, r, frame.proj, vec2(frame.viewport.xy));
    if (any(isnan(s))) return true;
    return floor(s.x) < float(rect.z) && float(rect.x) < ceil(s.z) && floor(s.y) < float(rect.w) &&
           float(rect.y) < ceil(s.w);
}

// Writes draw d's commands for light l from command `base` of its light's region: the runs
// of meshlets the light reaches (the meshlet sphere grown by the error of the camera-relative
// subtraction, include/meshlets.h, the light's range by a margin over evalLight's own test;
// without params.meshletReach those whose fragments can fall in its scissor; a directional
// light, TP_MPLD_FLAG_ALL, reaches every meshlet). Returns (commands, triangles).
uvec2 writeReachedRuns(LightDrawLight l, LightDrawDraw d, uint base) {
    const bool all = (l.flags & TP_MPLD_FLAG_ALL) != 0u;
    const vec3 eye = frame.eyeWorld.xyz; // what camera-relative positions are relative to
    const float eyeMagnitude = length(eye);
    uint written = 0u, triangles = 0u, first = 0u, end = 0u;
    bool open = false;
    for (uint k = 0u; k < d.meshletCount; ++k) {
        const MeshletGpu ml = meshlets[d.firstMeshlet + k];
        const float slack =
            (length(ml.center) + eyeMagnitude + ml.radius) * TP_MESHLET_POSITION_EPS;
        const vec3 centre = ml.center - eye;
        bool reached = all;
        if (!all && params.meshletReach != 0u) {
            const float reach = l.sphere.w * 1.0001 + ml.radius + slack;
            const vec3 between = centre - l.sphere.xyz;
            reached = dot(between, between) <= reach * reach;
        } else if (!all) {
            reached = inScissor(centre, ml.radius + slack, l.rect);
        }
        if (!reached) continue;
        if (open && end != ml.firstIndex && written + 1u < params.spansPerDraw) {
            triangles += writeCommand(base + written++, d, first, end);
            open = false;
        }
        if (!open) first = ml.firstIndex;
        open = true;
        end = ml.firstIndex + 3u * ml.triangleCount;
    }
    if (open) triangles += writeCommand(base + written++, d, first, end);
    return uvec2(written, triangles);
}

void main() {
    const uint slot = gl_GlobalInvocationID.x;
    if (slot >= params.lightCount || params.drawCount == 0u) return;
    const LightDrawLight l = lightRows[slot];
    const uint region = slot * params.drawCount * params.spansPerDraw,
               countBase = slot * params.runCount;
    uint run = 0u, n = 0u, total = 0u, triangles = 0u;
    for (uint i = 0u; i < params.drawCount; ++i) { // an explicit count (docs: LAVAPIPE.md)
        const LightDrawDraw d = drawRows[i];
        if (d.run != run) {
            counts[countBase + run] = n;
            run = d.run;
            n = 0u;
        }
        if (!mpLightTouchesDraw(l, d, params.boxTest != 0u)) continue;
        ++total;
        const uvec2 wrote = writeReachedRuns(l, d, region + d.runFirst * params.spansPerDraw + n);
        n += wrote.x;
        triangles += wrote.y;
    }
    counts[countBase + run] = n;
    meshes[slot] = uvec2(total, triangles);
}
