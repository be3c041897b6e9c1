#version 460
#extension GL_GOOGLE_include_directive : require
// The one vertex shader of every scene draw (prepass, G-buffer, forward, reference), so
// depth is bit-identical between passes and the EQUAL depth test after a prepass holds.
//   TP_VERT_POSITION_ONLY (scene_position_vert): only the position and the interpolated 1,
//   for the blended depth bounds (blended_bounds.frag), which read nothing else; the same
//   source lines compute gl_Position and both outputs, so they are those of the full variant.
//   On lavapipe every output costs per vertex and every interpolant per triangle and per
//   fragment block (docs/clustered.md, "The blended depth bounds on lavapipe").
//   TP_VERT_MESHLET_TRIANGLE (scene_meshlet_vert, scene_position_meshlet_vert): also the
//   culled meshlet's first triangle, flat (the visibility pass's ids, include/meshlets.h).
//   TP_VERT_MATERIAL_INSTANCE (scene_material_vert): the material index from firstInstance,
//   flat (multipass forward's indirect light draws: many materials in one call).
#include "include/shared.h"
#include "include/scene_bindings.glsl"
#ifdef TP_VERT_MESHLET_TRIANGLE
#include "include/meshlets.h"
layout(location = TP_LOCATION_MESHLET_TRIANGLE) flat out uint outMeshletTriangle;
#endif

#ifdef TP_VERT_MATERIAL_INSTANCE
layout(location = TP_LOCATION_MATERIAL) flat out uint outMaterial;
#endif

layout(location = 0) out vec3 outPosition;
#ifndef TP_VERT_POSITION_ONLY
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
layout(location = 3) out vec4 outTangent;
layout(location = 4) out vec4 outColor;
#endif
// 1 at every vertex, interpolated like the others: the fragment stage divides every
// interpolant by it (scene_inputs.glsl). Exactly 1 on a correct device; on lavapipe, whose
// per-sample interpolation divides by 1/w at the pixel centre instead of at the sample, it
// is the factor that undoes that (docs/shading.md, "Where a sample is shaded").
layout(location = 5) out float outOne;

// `precise` (NoContraction) instead of `invariant gl_Position`: the validation layers of
// Debian 12 reject the Invariant decoration glslang puts on the gl_PerVertex member, and
// forbidding FMA contraction is what keeps the position bit-identical across pipelines.

// Camera-relative (shared.h, FrameUniforms): the position leaves here minus the eye, so the
// rasterizer, the interpolants and the shading never carry the eye's magnitude. Far from the
// origin (|p|, |eye| ~ 1e6 and |p - eye| < |eye|) the subtraction is exact (Sterbenz); near it
// the result is correctly rounded. The vertices are world space with no model transform.

void main() {
    Vertex v = vertices[gl_VertexIndex];
    precise vec3 relative = v.positionU.xyz - frame.eyeWorld.xyz;
    outPosition = relative;
#ifndef TP_VERT_POSITION_ONLY
    outNormal = v.normalV.xyz;
    outUv = vec2(v.positionU.w, v.normalV.w);
    outTangent = v.tangent;
    outColor = v.color;
#endif
    outOne = frame.projParams.z;
#ifdef TP_VERT_MATERIAL_INSTANCE
    outMaterial = uint(gl_InstanceIndex); // firstInstance: one instance per command
#endif
#ifdef TP_VERT_MESHLET_TRIANGLE
    outMeshletTriangle = uint(gl_InstanceIndex); // firstInstance: one instance per command
#endif
    precise vec4 clip = frame.viewProj * vec4(relative, 1.0);
    gl_Position = clip;
}
