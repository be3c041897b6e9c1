#version 460
#extension GL_GOOGLE_include_directive : require
// One pixel of the viewer's scene area (viewer/composite.h states the rules; this is its GPU
// twin): split (tonemapped A | B, the divider), or the difference heat map. Writes the target's
// RGBA8 bytes in its channel order; the legend rows below are the CPU's (copied in).
#include "viewer/composite_shared.h"
#include "include/tonemap.h"

layout(local_size_x = TP_VC_GROUP, local_size_y = TP_VC_GROUP) in;

#include "viewer/composite_common.glsl"
layout(std430, set = 1, binding = TP_VC_BINDING_OUT) writeonly buffer Out { uint pixels[]; };
layout(std430, set = 1, binding = TP_VC_BINDING_STATS) readonly buffer Ramp { vec4 ramp[TP_VC_RAMP_COLOURS]; };

// The CPU's toByte: NaN and negatives to 0, rounded half away from zero.
uint toByte(float v) {
    if (!(v >= 0.0)) return 0u;
    return uint(floor(min(v, 1.0) * 255.0 + 0.5));
}

uint pack(vec3 c) {
    const uvec3 b = uvec3(toByte(c.r), toByte(c.g), toByte(c.b));
    return pc.swapRB != 0u ? (b.b | (b.g << 8) | (b.r << 16) | (255u << 24))
                           : (b.r | (b.g << 8) | (b.b << 16) | (255u << 24));
}

vec3 heat(float t) {
    t = clamp(t, 0.0, 1.0) * float(TP_VC_RAMP_COLOURS - 1);
    const uint i = min(uint(t), uint(TP_VC_RAMP_COLOURS - 2));
    const float f = t - float(i);
    return ramp[i].rgb + f * (ramp[i + 1u].rgb - ramp[i].rgb);
}

// The side's texel for output pixel p, nearest-scaled as composite.cpp's blit (a side of another
// size: the reference of the previous resolution while the new one renders).
vec3 fetchScaled(sampler2D image, ivec2 p) {
    const uvec2 size = uvec2(textureSize(image, 0));
    return texelFetch(image, ivec2(uvec2(p) * size / uvec2(pc.width, pc.height)), 0).rgb;
}

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= int(pc.width) || p.y >= int(pc.height)) return;
    vec3 colour = vec3(0.0);
    if (pc.mode == TP_VC_DIFFERENCE) {
        bool allFinite;
        const float v = differenceAt(p, allFinite);
        if (!allFinite)
            colour = vec3(1.0, 0.0, 1.0); // magenta: not on the ramp
        else
            colour = heat(pc.diffScale > 0.0 ? v / pc.diffScale : (v > 0.0 ? 1.0 : 0.0));
    } else if (uint(p.x) == pc.divider) {
        colour = vec3(255.0, 176.0, 0.0) / 255.0; // kDividerRgb
    } else {
        const bool right = uint(p.x) >= pc.boundary;
        if ((pc.sides & (right ? 2u : 1u)) != 0u) {
            const vec3 linear = right ? fetchScaled(rightImage, p) : fetchScaled(leftImage, p);
            colour = tonemap(linear, pc.exposureEv);
        }
    }
    pixels[p.y * int(pc.width) + p.x] = pack(colour);
}
