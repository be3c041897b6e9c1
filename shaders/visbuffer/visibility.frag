#version 460
#extension GL_GOOGLE_include_directive : require
// The visibility pass: depth and the packed (draw, triangle) id of the visible surface per
// sample (vis_shared.h), nothing else. Opaque draws run this with scene.vert's position-only
// variant. TP_VIS_MASKED (alpha-masked draws): the material's alpha is tested first, per
// sample under MSAA (`sample` inputs force it, as in the depth prepass, prepass_mask.frag), so
// each sample's id is the surface the reference sees there.
#include "include/shared.h"
#include "visbuffer/vis_shared.h"
#include "include/scene_bindings.glsl"
#ifdef TP_VIS_MASKED
#include "include/material.glsl"
#include "include/scene_inputs.glsl"
#endif
#ifdef TP_VIS_MESHLETS
// --cull-geometry frustum: drawn as meshlets, whose gl_PrimitiveID counts from 0 in each
// indirect command and in meshlet order. The meshlet's first triangle (scene.vert, from
// firstInstance) plus gl_PrimitiveID indexes the scene's map back to the draw's triangle, so
// the id is the one the whole draw writes and the resolve reads the same triangle.
#include "include/meshlets.h"
layout(location = TP_LOCATION_MESHLET_TRIANGLE) flat in uint inMeshletTriangle;
layout(std430, set = TP_SET_PASS, binding = TP_VIS_BINDING_SOURCE_TRIANGLES) readonly buffer
    SourceTriangleBlock {
    uint sourceTriangles[];
};
#endif

layout(constant_id = TP_VIS_SPEC_TRIANGLE_BITS) const uint kTriangleBits = 20u;
layout(location = 0) out float outId; // the id's integer value, exact (vis_shared.h)

void main() {
#ifdef TP_VIS_MASKED
    MaterialSample ms = evalFragmentMaterial();
    if (ms.alpha < materials[draw.materialIndex].alphaCutoff) discard;
#endif
    // The draw's row in the VisDraw table comes in the push constant's pad0 (recordDraw).
#ifdef TP_VIS_MESHLETS
    const uint triangle = sourceTriangles[inMeshletTriangle + uint(gl_PrimitiveID)];
#else
    const uint triangle = uint(gl_PrimitiveID);
#endif
    outId = float(((draw.pad0 + 1u) << kTriangleBits) | triangle);
}
