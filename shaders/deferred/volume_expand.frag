#version 460
#extension GL_GOOGLE_include_directive : require
// Volumes lighting of a blended scene under MSAA: the hybrid forward pass blends per
// sample into hdr_msaa, so the lit (resolved) opaque radiance is copied to every sample.
// Blending is linear in the destination, so this is exact wherever a blended surface
// covers all samples of a pixel or none; see docs/deferred.md for where it is not.
#include "include/shared.h"

layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_HDR) uniform sampler2D hdrIn;
layout(location = 0) out vec4 outColor;

void main() { outColor = texelFetch(hdrIn, ivec2(gl_FragCoord.xy), 0); }
