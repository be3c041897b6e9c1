#version 460
#extension GL_GOOGLE_include_directive : require
// The depth pyramid pass (core/passes/depth_pyramid.h): one dispatch per level, a texel per
// invocation, each the smallest depth (reverse-Z: the farthest surface) of the 2x2 texels of
// the level below, or for level 0 of the 2x2 pixels of the depth image and every sample of
// each (TP_DP_MSAA: a sampler2DMS). Texels past the frame's edge are skipped, not clamped to
// a neighbour: the minimum is over exactly the pixels the texel covers (passes/depth_pyramid.h).
#include "include/shared.h"
#include "passes/depth_pyramid.h"

layout(local_size_x = TP_DP_GROUP, local_size_y = TP_DP_GROUP) in;

layout(push_constant) uniform PushBlock {
    DepthPyramidPush push;
};
#ifdef TP_DP_MSAA
layout(set = TP_SET_PASS, binding = TP_DP_BINDING_DEPTH) uniform sampler2DMS depthImage;
#else
layout(set = TP_SET_PASS, binding = TP_DP_BINDING_DEPTH) uniform sampler2D depthImage;
#endif
layout(std430, set = TP_SET_PASS, binding = TP_DP_BINDING_PYRAMID) buffer PyramidBlock {
    float texels[];
};

// The farthest sample of pixel p (every sample under MSAA).
float pixelMin(ivec2 p) {
#ifdef TP_DP_MSAA
    float d = texelFetch(depthImage, p, 0).r;
    for (int s = 1; s < int(push.samples); ++s)
        d = min(d, texelFetch(depthImage, p, s).r);
    return d;
#else
    return texelFetch(depthImage, p, 0).r;
#endif
}

void main() {
    const uint level = push.level;
    const uvec2 size = pyramidLevelSize(push.width, push.height, level);
    const uvec2 t = gl_GlobalInvocationID.xy;
    if (t.x >= size.x || t.y >= size.y) return;
    // What the texel covers one level down: the frame's pixels (level 0) or level - 1's texels.
    const uvec2 below = level == 0u ? uvec2(push.width, push.height)
                                    : pyramidLevelSize(push.width, push.height, level - 1u);
    const uint belowOffset = level == 0u ? 0u : pyramidLevelOffset(push.width, push.height, level - 1u);
    float d = 1.0; // reverse-Z: the nearest possible depth, replaced by the first sample below
    for (uint j = 0u; j < 2u; ++j)
        for (uint i = 0u; i < 2u; ++i) {
            const uvec2 q = t * 2u + uvec2(i, j);
            if (q.x >= below.x || q.y >= below.y) continue; // past the frame's edge
            d = min(d, level == 0u ? pixelMin(ivec2(q)) : texels[belowOffset + q.y * below.x + q.x]);
        }
    texels[pyramidLevelOffset(push.width, push.height, level) + t.y * size.x + t.x] = d;
}
