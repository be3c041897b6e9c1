#version 460
#extension GL_GOOGLE_include_directive : require
// A colour image set to one value by compute (core/passes/image_clear.h), every sample of
// every pixel. A render pass's clear runs on the graphics SMs: on the H200, 4 of 132, about
// 55 GB/s; here every SM writes. TP_IC_FORMAT: the storage image's format qualifier;
// TP_IC_MS: a multisampled image.
#include "include/shared.h"
#include "passes/image_clear.h"

layout(local_size_x = TP_IC_GROUP, local_size_y = TP_IC_GROUP) in;
layout(constant_id = TP_IC_SPEC_SAMPLES) const uint kSamples = 1u;
layout(constant_id = TP_IC_SPEC_VALUE + 0) const uint kR = 0u;
layout(constant_id = TP_IC_SPEC_VALUE + 1) const uint kG = 0u;
layout(constant_id = TP_IC_SPEC_VALUE + 2) const uint kB = 0u;
layout(constant_id = TP_IC_SPEC_VALUE + 3) const uint kA = 0u;
#ifdef TP_IC_MS
layout(set = TP_SET_PASS, binding = TP_IC_BINDING_IMAGE, TP_IC_FORMAT) uniform writeonly image2DMS target;
#else
layout(set = TP_SET_PASS, binding = TP_IC_BINDING_IMAGE, TP_IC_FORMAT) uniform writeonly image2D target;
#endif

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(target)))) return;
    const vec4 v = uintBitsToFloat(uvec4(kR, kG, kB, kA));
#ifdef TP_IC_MS
    for (int s = 0; s < int(kSamples); ++s) imageStore(target, p, s, v);
#else
    imageStore(target, p, v);
#endif
}
