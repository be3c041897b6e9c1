#version 460
#extension GL_GOOGLE_include_directive : require
// One microbenchmark of `triptych calibrate` (TP_CAL_KIND, calibrate_shared.h): a loop whose
// work the C++ counts exactly (bytes moved, FMAs, fetches, light evaluations, atomics), so
// that work / time is a rate of the device. Step k of invocation gid touches vec4
// (gid + k * stride) & mask: neighbouring invocations touch neighbouring vec4 (whole cache
// lines), and a long loop wraps around the buffer, passing over it again. Every result can
// reach memory, so no compiler removes a loop.
#include "calibrate/calibrate_shared.h"
#include "calibrate/calibrate_fma.glsl"
#include "calibrate/calibrate_light.glsl"
#include "calibrate/calibrate_texture.glsl"

layout(local_size_x = TP_CAL_GROUP_SIZE) in;

layout(std430, set = 1, binding = TP_CAL_BINDING_SRC) readonly buffer Src { vec4 src[]; };
#if TP_CAL_KIND == TP_CAL_SHARED_ATOMIC || TP_CAL_KIND == TP_CAL_GLOBAL_ATOMIC
layout(std430, set = 1, binding = TP_CAL_BINDING_DST) buffer Dst { uint words[]; };
#else
layout(std430, set = 1, binding = TP_CAL_BINDING_DST) buffer Dst { vec4 dst[]; };
#endif
layout(push_constant) uniform Push { CalPush cal; };

shared uint sWords[TP_CAL_GROUP_SIZE];

void main() {
    const uint gid = gl_GlobalInvocationID.x;
#if TP_CAL_KIND == TP_CAL_READ || TP_CAL_KIND == TP_CAL_CACHE_READ
    vec4 acc = vec4(0.0);
    for (uint k = 0u; k < cal.iterations; ++k)
        acc += src[(gid + k * cal.stride) & cal.mask];
    // Never true for the data calibrate uploads (zeros); the compiler cannot know that.
    if (acc.x == 1.0e-30) dst[gid] = acc;
#elif TP_CAL_KIND == TP_CAL_WRITE
    for (uint k = 0u; k < cal.iterations; ++k)
        dst[(gid + k * cal.stride) & cal.mask] = vec4(float(k), float(gid), 0.0, 1.0);
#elif TP_CAL_KIND == TP_CAL_COPY
    for (uint k = 0u; k < cal.iterations; ++k) {
        const uint i = (gid + k * cal.stride) & cal.mask;
        dst[i] = src[i];
    }
#elif TP_CAL_KIND == TP_CAL_FMA
    const vec4 sum = fmaChains(float(gid), cal.iterations);
    if (sum.x == 1.0e-30) dst[gid] = sum;
#elif TP_CAL_KIND == TP_CAL_TEXTURE
    const uvec2 texel = uvec2(gid & uint(TP_CAL_TEXTURE_SIZE - 1), (gid / uint(TP_CAL_TEXTURE_SIZE)) & uint(TP_CAL_TEXTURE_SIZE - 1));
    const vec4 sum = textureFetches(vec2(texel), cal.iterations);
    if (sum.x == 1.0e-30) dst[gid] = sum;
#elif TP_CAL_KIND == TP_CAL_IMAGE_READ
    const ivec2 texel = ivec2(gid & uint(TP_CAL_TEXTURE_SIZE - 1), (gid / uint(TP_CAL_TEXTURE_SIZE)) & uint(TP_CAL_TEXTURE_SIZE - 1));
    const vec4 sum = texelReads(texel, cal.iterations);
    if (sum.x == 1.0e-30) dst[gid] = sum;
#elif TP_CAL_KIND == TP_CAL_IMAGE_READ_MSAA4
    const ivec2 texel = ivec2(gid & uint(TP_CAL_TEXTURE_SIZE - 1), (gid / uint(TP_CAL_TEXTURE_SIZE)) & uint(TP_CAL_TEXTURE_SIZE - 1));
    const float sum = sampleReads(texel, cal.iterations);
    if (sum == 1.0e-30) dst[gid] = vec4(sum);
#elif TP_CAL_KIND == TP_CAL_LIGHT_POINT || TP_CAL_KIND == TP_CAL_LIGHT_SPOT
    const vec3 sum = lightEvaluations(float(gid), cal.iterations, TP_CAL_KIND == TP_CAL_LIGHT_SPOT);
    if (sum.x == 1.0e-30) dst[gid] = vec4(sum, 1.0);
#elif TP_CAL_KIND == TP_CAL_SHARED_ATOMIC
    const uint lid = gl_LocalInvocationID.x;
    sWords[lid] = 0u;
    barrier();
    for (uint k = 0u; k < cal.iterations; ++k)
        atomicAdd(sWords[(lid + k) & uint(TP_CAL_GROUP_SIZE - 1)], 1u);
    barrier();
    if (sWords[lid] == 0xffffffffu) words[gid] = sWords[lid];
#elif TP_CAL_KIND == TP_CAL_GLOBAL_ATOMIC
    for (uint k = 0u; k < cal.iterations; ++k)
        atomicAdd(words[(gid + k * cal.stride) & cal.mask], 1u);
#endif
}
