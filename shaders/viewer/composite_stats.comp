#version 460
#extension GL_GOOGLE_include_directive : require
// The figures the composite needs from the images, without reading them back
// (viewer/gpu_composite.cpp): TP_VC_STATS picks one (composite_shared.h).
//   LOG_LUMINANCE: per workgroup, the sum of log(Rec.709 luminance) over its finite pixels of
//     positive luminance and their count (the CPU adds the partial sums in double:
//     core/image/tonemap.cpp autoExposureEv's rule).
//   HIGH/LOW_HISTOGRAM: the 99th percentile of max-channel |A - B| exactly, as a radix select
//     over the value's bits (non-negative floats order as their bits): the high 16 bits' bins,
//     then the low 16 bits' of the values in the chosen high bin (compare's rule,
//     differencePercentile99).
#include "viewer/composite_shared.h"

layout(local_size_x = TP_VC_GROUP, local_size_y = TP_VC_GROUP) in;

#include "viewer/composite_common.glsl"
layout(std430, set = 1, binding = TP_VC_BINDING_STATS) buffer Stats { uint words[]; };

#if TP_VC_STATS == TP_VC_LOG_LUMINANCE
shared float sSum[TP_VC_GROUP * TP_VC_GROUP];
shared uint sCount[TP_VC_GROUP * TP_VC_GROUP];
#endif

void main() {
    const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    const bool inside = p.x < int(pc.width) && p.y < int(pc.height);
#if TP_VC_STATS == TP_VC_LOG_LUMINANCE
    float sum = 0.0;
    uint count = 0u;
    if (inside) {
        const vec3 c = texelFetch(leftImage, p, 0).rgb;
        const float l = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
        if (!(any(isnan(c)) || any(isinf(c))) && l > 0.0) {
            sum = log(l);
            count = 1u;
        }
    }
    const uint i = gl_LocalInvocationIndex;
    sSum[i] = sum;
    sCount[i] = count;
    barrier();
    for (uint s = (TP_VC_GROUP * TP_VC_GROUP) / 2u; s > 0u; s >>= 1u) {
        if (i < s) {
            sSum[i] += sSum[i + s];
            sCount[i] += sCount[i + s];
        }
        barrier();
    }
    if (i == 0u) {
        const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
        words[group * 2u] = floatBitsToUint(sSum[0]);
        words[group * 2u + 1u] = sCount[0];
    }
#else
    if (!inside) return;
    bool allFinite;
    const float v = differenceAt(p, allFinite);
    if (isnan(v) || isinf(v)) return; // the CPU's rule: the value, not each channel
    const uint bits = floatBitsToUint(v);
#if TP_VC_STATS == TP_VC_HIGH_HISTOGRAM
    atomicAdd(words[bits >> 16], 1u);
    atomicAdd(words[65536], 1u); // the finite values
#else
    if ((bits >> 16) == pc.prefix) atomicAdd(words[bits & 0xffffu], 1u);
#endif
#endif
}
