// The shadow maps' side of the compute rasterizer (shadow_raster.comp, shadow_raster_big.comp;
// core/passes/shadow_raster.h, docs/shadows.md "Rasterizing the maps in compute"): the triangle
// is include/raster_triangle.glsl's (the visibility buffer's); here the view is a shadow face,
// as ShadowMaps::recordFaces gives it to the hardware: shadow.vert's light-relative clip
// positions, the face's square of the map as viewport and scissor (positive height: no flip),
// one sample at the texel's centre, both faces of every triangle (VK_CULL_MODE_NONE); the
// depth (reverse-Z, near / distance: nearest = largest) kept as its float's bits with a 32-bit
// atomic max, which orders positive floats as their values; 0 is the hardware's clear value.
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "include/shared.h"
#include "include/shadows.h"
#include "shadow/shadow_cull.h"
#include "shadow/shadow_raster.h"
#include "include/scene_bindings.glsl"

const uint kSamples = 1u; // a map is single-sampled: the texel's centre
layout(constant_id = TP_SR_SPEC_WIDTH) const uint kMapWidth = 1u;
layout(constant_id = TP_SR_SPEC_LOCAL) const uint kLocal = 0u;
#include "include/sample_locations.glsl"

layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_DEPTH) buffer DepthBlock {
    uint mapDepth[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_ROWS) readonly buffer RowBlock {
    ShadowCullRow rows[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_FACES) readonly buffer FaceBlock {
    ShadowFace faces[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_LIST) buffer ListBlock {
    uint list[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_OVERFLOW) buffer OverflowBlock {
    uint overflowSlots[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_INDICES) readonly buffer IndexBlock {
    uint meshletIndices[];
};
layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_COMMANDS) readonly buffer CommandBlock {
    uint commands[]; // VkDrawIndexedIndirectCommand, 5 words each
};
layout(std430, set = TP_SET_PASS, binding = TP_SR_BINDING_COUNTS) readonly buffer CountBlock {
    uint counts[];
};

#include "include/raster_triangle.glsl"

// The face being rasterized by this invocation (useFace).
mat4 gProj;
vec3 gLight;
ivec2 gOrigin, gEdge;
mat4 gInverse; // masked rows only

void useFace(uint face, bool masked) {
    ShadowFace f = faces[face];
    gProj = f.lightProj;
    gLight = lights[f.atlas.w].position; // camera-relative, as shadow.vert subtracts it
    gOrigin = ivec2(kLocal != 0u ? f.local.xy : f.atlas.xy);
    gEdge = ivec2(f.atlas.z);
    if (masked) gInverse = inverse(f.lightProj);
}

// Shadow.vert's clip position of vertex `index` (the same `precise` operations).
vec4 clipPosition(uint index) {
    Vertex v = vertices[index];
    precise vec3 relative = v.positionU.xyz - frame.eyeWorld.xyz;
    precise vec3 fromLight = relative - gLight;
    precise vec4 clip = gProj * vec4(fromLight, 1.0);
    return clip;
}

vec3 rasterRelative(uint index) {
    return (vertices[index].positionU.xyz - frame.eyeWorld.xyz) - gLight;
}

// The ray from the light (the origin) through texel point fc: the point of the near plane
// (depth 1) it meets.
vec3 rasterRayDir(vec2 fc) {
    vec2 ndc = (fc - vec2(gOrigin)) / vec2(gEdge) * 2.0 - 1.0;
    vec4 p = gInverse * vec4(ndc, 1.0, 1.0);
    return p.xyz / p.w;
}

ivec2 rasterViewOrigin() { return gOrigin; }
ivec2 rasterViewSize() { return gEdge; }
bool rasterFlipY() { return false; }

uint rasterSample(ivec2 px, uint k, vec2 fc, float z, uint id, bool masked, MaskTriangle mt) {
    uint slot = uint(px.y) * kMapWidth + uint(px.x);
    uint bits = floatBitsToUint(min(z, 1.0)); // the viewport's depth range [0, 1]
    if (mapDepth[slot] >= bits) return 0u; // hidden: no atomic (and no texture fetch)
    if (masked && maskAlpha(mt, fc) < materials[mt.material].alphaCutoff) return 0u;
    atomicMax(mapDepth[slot], bits);
    return 1u;
}

// The row whose command range holds command `slot`: the last row starting at or before it
// (the rows are sorted by firstCommand, padding rows at the end; shadow/shadow_cull.h).
uint rowOfCommand(uint slot) {
    uint lo = 0u, hi = uint(rows.length()); // rows[lo].firstCommand <= slot < rows[hi]'s
    while (hi - lo > 1u) {
        uint mid = (lo + hi) / 2u;
        if (rows[mid].firstCommand <= slot) lo = mid; else hi = mid;
    }
    return lo;
}

// Triangle t of the meshlet in command slot `slot`, which its row `r` kept (k below counts[r]),
// its vertices (vertexOffset added); false past the meshlet's triangles.
bool commandTriangle(uint slot, uint t, out uint i0, out uint i1, out uint i2) {
    uint cmd = 5u * slot;
    if (t >= commands[cmd] / 3u) return false;
    uint base = commands[cmd + 2u] + 3u * t;
    int vertexOffset = int(commands[cmd + 3u]);
    i0 = uint(int(meshletIndices[base]) + vertexOffset);
    i1 = uint(int(meshletIndices[base + 1u]) + vertexOffset);
    i2 = uint(int(meshletIndices[base + 2u]) + vertexOffset);
    return true;
}

// Whether row r kept a meshlet in command slot `slot` of its range.
bool slotKept(uint slot, uint r) {
    uint k = slot - rows[r].firstCommand; // the command's place in its row's range
    return k < rows[r].meshletCount && k < counts[r];
}

// Triangle t of the meshlet in command slot `slot`, its vertices (vertexOffset added) and its
// row `r`; false when there is none (a slot past its row's kept commands, t past the meshlet).
bool slotTriangle(uint slot, uint t, out uint i0, out uint i1, out uint i2, out uint r) {
    if (slot >= uint(commands.length()) / 5u) return false;
    r = rowOfCommand(slot);
    return slotKept(slot, r) && commandTriangle(slot, t, i0, i1, i2);
}
