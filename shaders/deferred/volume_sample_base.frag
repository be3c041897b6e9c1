#version 460
#extension GL_GOOGLE_include_directive : require
// Volumes lighting of a blended scene under MSAA: the hybrid forward pass blends per sample
// into hdr_msaa, so the opaque radiance under it must be per sample too (a pixel-average
// copied to every sample is wrong wherever a blended surface's alpha or the opaque surface
// under it differs between samples). Each sample invocation writes what the tiled pass's
// first batch writes before its lights: ambient + emissive of its own sample on an edge
// pixel (the base pass's 1x edge mask), the pixel's one value elsewhere. The light volumes
// then add into hdr_msaa per sample (volume_light.frag, TP_HDR_MSAA).
//   TP_EMISSIVE (0/1): the G-buffer has an emissive target.
#define TP_MSAA 1
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"
#include "deferred/gbuffer_read.glsl"

layout(set = TP_SET_PASS, binding = TP_DEF_BINDING_EDGE_MASK) uniform sampler2D gEdge;
layout(location = 0) out vec4 outHdr;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uint s = uint(gl_SampleID);
    vec3 c = vec3(0.0);
    if (texelFetch(gEdge, p, 0).r > 0.5) {
        if (fetchDepth(p, s) > 0.0) c = ambientEmissive(p, s);
    } else if (meanDepth(p) > 0.0) {
        c = ambientEmissive(p, 0u);
    }
    outHdr = vec4(c, 1.0);
}
