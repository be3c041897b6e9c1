#version 460
#extension GL_GOOGLE_include_directive : require
// Light-volume base pass (full screen): writes hdr = ambient + emissive once per pixel,
// before any light volume adds to it. Under MSAA (TP_MSAA) it also finds the edge pixels
// (Lauritzen 2010, the tiled pass's test) into the 1x edge mask and writes the 1x depth
// the light volumes test against: the nearest sample (a surface inside a volume is in
// front of its back face at every sample, so the back face is behind the nearest one), or
// 1 on edge pixels, which then always pass and are shaded per sample.
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"
#include "deferred/gbuffer_read.glsl"

layout(location = 0) out vec4 outHdr;
#ifdef TP_MSAA
layout(location = 1) out vec4 outEdge;
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = vec3(0.0);
#ifdef TP_MSAA
    bool edge = isEdge(p);
    float nearest = 0.0;
    for (uint s = 0u; s < kSamples; ++s) nearest = max(nearest, fetchDepth(p, s));
    if (edge) {
        for (uint s = 0u; s < kSamples; ++s)
            if (fetchDepth(p, s) > 0.0) c += ambientEmissive(p, s);
        c /= float(kSamples);
    } else if (meanDepth(p) > 0.0) {
        c = ambientEmissive(p, 0u);
    }
    gl_FragDepth = edge ? 1.0 : nearest;
    outEdge = vec4(edge ? 1.0 : 0.0, 0.0, 0.0, 1.0);
#else
    if (fetchDepth(p, 0u) > 0.0) c = ambientEmissive(p, 0u);
#endif
    outHdr = vec4(c, 1.0);
}
