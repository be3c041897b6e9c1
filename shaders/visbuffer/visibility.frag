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

layout(constant_id = TP_VIS_SPEC_TRIANGLE_BITS) const uint kTriangleBits = 20u;
layout(location = 0) out float outId; // the id's integer value, exact (vis_shared.h)

void main() {
#ifdef TP_VIS_MASKED
    MaterialSample ms = evalFragmentMaterial();
    if (ms.alpha < materials[draw.materialIndex].alphaCutoff) discard;
#endif
    // The draw's row in the VisDraw table comes in the push constant's pad0 (recordDraw).
    outId = float(((draw.pad0 + 1u) << kTriangleBits) | uint(gl_PrimitiveID));
}
