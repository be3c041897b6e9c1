// The depth pyramid pass (core/passes/depth_pyramid.h, passes/depth_pyramid.comp) and the
// late meshlet cull that reads it (passes/meshlet_cull.comp, TP_MC_PHASE_LATE): its bindings,
// its push constant and the layout of its levels in one buffer. docs/geometry.md, "Occlusion".
//
// Reverse-Z (0 is the far plane): each texel holds the SMALLEST depth, the farthest surface,
// of the pixels (and, under MSAA, the samples) it covers, so a meshlet whose nearest point is
// nearer than that can be seen somewhere in the texel and one wholly farther cannot.
// Level L is ceil(w / 2^(L+1)) x ceil(h / 2^(L+1)) texels (level 0 is half the frame), and its
// texel t covers exactly the pixels [t 2^(L+1), (t+1) 2^(L+1)) of the frame, clipped to it: no
// rounding of a non-power-of-two size lets a texel miss a pixel. The levels go down to 1x1.
#ifndef TP_DEPTH_PYRAMID_H
#define TP_DEPTH_PYRAMID_H
#include "include/glsl_cpp.h"

#define TP_DP_BINDING_DEPTH 0   // the depth written by the first phase (sampler2D[MS])
#define TP_DP_BINDING_PYRAMID 1 // float[]: every level, level 0 first, rows of texels
#define TP_DP_GROUP 8           // 8x8 invocations, a texel each

#ifndef TP_GLSL
namespace tp::gpu {
#endif

// The pass's push constant (the scene layout's 16 bytes): the level written and the frame.
TP_STRUCT(DepthPyramidPush) {
    uint level;
    uint width;   // the frame's pixels
    uint height;
    uint samples; // of the depth image (1: a single-sample image)
};

// Texels of level `level` across and down: ceil(n / 2^(level+1)).
TP_INLINE uvec2 pyramidLevelSize(uint width, uint height, uint level) {
    return uvec2(((width - 1u) >> (level + 1u)) + 1u, ((height - 1u) >> (level + 1u)) + 1u);
}

// Levels down to 1x1: the bit length of max(w, h) - 1, at least one.
TP_INLINE uint pyramidLevels(uint width, uint height) {
    uint n = max(width, height) - 1u;
    uint levels = 0u;
    while (n > 0u) {
        n >>= 1u;
        ++levels;
    }
    return max(levels, 1u);
}

// Where level `level` starts in the buffer, in texels (pyramidLevelOffset(w, h, levels): the
// whole pyramid's size).
TP_INLINE uint pyramidLevelOffset(uint width, uint height, uint level) {
    uint offset = 0u;
    for (uint l = 0u; l < level; ++l) {
        const uvec2 s = pyramidLevelSize(width, height, l);
        offset += s.x * s.y;
    }
    return offset;
}

#ifndef TP_GLSL
static_assert(sizeof(DepthPyramidPush) == 16);
} // namespace tp::gpu
#endif
#endif
