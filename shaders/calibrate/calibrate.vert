#version 460
#extension GL_GOOGLE_include_directive : require
// The geometry of calibrate's fragment, raster and triangle ceilings (TP_CAL_VERTEX):
// TP_CAL_VERTEX_LAYERS draws one full-screen triangle per instance; TP_CAL_VERTEX_GRID covers
// the target with `stride` x `stride` cells of two triangles each (non-indexed: 6 vertices a
// cell), per instance; TP_CAL_VERTEX_GRID_INDEXED the same cells over shared vertices (an index
// buffer, rig.cpp), as a mesh is drawn. Each instance is nearer than the last (reverse-Z,
// depth test GREATER), so with a depth attachment every fragment of every layer passes and
// writes: no early rejection, and a depth ceiling that measures what a depth pass pays.
#include "calibrate/calibrate_shared.h"

layout(push_constant) uniform Push { CalPush cal; };

void main() {
    const float depth = float(gl_InstanceIndex + 1) / float(cal.iterations + 1u);
#if TP_CAL_VERTEX == TP_CAL_VERTEX_LAYERS
    const vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(uv * 2.0 - 1.0, depth, 1.0);
#elif TP_CAL_VERTEX == TP_CAL_VERTEX_GRID_INDEXED
    const uint row = cal.stride + 1u;
    const uvec2 at = uvec2(uint(gl_VertexIndex) % row, uint(gl_VertexIndex) / row);
    gl_Position = vec4(vec2(at) / float(cal.stride) * 2.0 - 1.0, depth, 1.0);
#else
    const uvec2 corners[6] = uvec2[6](uvec2(0, 0), uvec2(1, 0), uvec2(0, 1), uvec2(1, 0), uvec2(1, 1), uvec2(0, 1));
    const uint cell = uint(gl_VertexIndex) / 6u;
    const uvec2 at = uvec2(cell % cal.stride, cell / cal.stride) + corners[uint(gl_VertexIndex) % 6u];
    gl_Position = vec4(vec2(at) / float(cal.stride) * 2.0 - 1.0, depth, 1.0);
#endif
}
