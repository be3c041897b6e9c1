#version 460
#extension GL_GOOGLE_include_directive : require
// Hybrid mode (--vis-raster hybrid): the triangles vis_raster listed for the hardware (too large
// for an invocation, or cut by the near plane), drawn as one non-indexed indirect draw from the
// list vis_raster_order packed in the draws' triangle order, with the vertex count it wrote:
// vertex k of listed triangle t is the list's index there, with scene.vert's very operations
// (`precise`), so its gl_Position is the one a whole draw gives.
#include "include/shared.h"
#include "visbuffer/vis_raster.h"
#include "include/scene_bindings.glsl"

layout(std430, set = TP_SET_PASS, binding = TP_VR_BINDING_VIS_LIST) readonly buffer ListBlock {
    uint list[];
};
layout(location = 0) flat out uint outId;

void main() {
    uint at = 4u * (uint(gl_VertexIndex) / 3u);
    Vertex v = vertices[list[at + uint(gl_VertexIndex) % 3u]];
    precise vec3 relative = v.positionU.xyz - frame.eyeWorld.xyz;
    outId = list[at + 3u];
    precise vec4 clip = frame.viewProj * vec4(relative, 1.0);
    gl_Position = clip;
}
