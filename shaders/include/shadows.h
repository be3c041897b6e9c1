// Shadow maps (core/passes/shadow_maps.h, docs/shadows.md): what crosses between the CPU plan
// (core/passes/shadow_planner.h) and the shaders that render and sample the maps. Shared by C++
// and GLSL; include after shared.h.
//
// A shadowed light has consecutive ShadowFace records (LightGpu.shadow = 1 + its first): six
// for a point light (a cube: +X, -X, +Y, -Y, +Z, -Z, each a 90-degree perspective face) and
// one for a spot (its cone). Every face is a square of texels in a depth map: in the resident
// atlas of the atlas pipelines (`atlas` rect), or in the one light's map the per-light
// pipelines render and reuse (`local` rect: the faces of one light in a 3 x 2 block).
//
// Positions are light-relative: p - light.position, both camera-relative as the shaders have
// them (shared.h), so a map does not depend on where the camera is. The projection is
// reverse-Z with an infinite far plane: the stored depth is near / distance along the face's
// axis, so distance = near / depth exactly (clip w is that distance).
#ifndef TP_SHADOWS_H
#define TP_SHADOWS_H
#include "include/shared.h"

#define TP_SET_SHADOW 2                // the shadow set, after the scene (0) and a pass's own (1)
#define TP_BINDING_SHADOW_FACES 0      // buffer ShadowFace[]
#define TP_BINDING_SHADOW_MAP 1        // sampler2D: the depth map (atlas or one light's)
#define TP_BINDING_SHADOW_DEPTH 2      // uint[]: the compute rasterizer's atlas depth (TP_SPEC_SHADOW_BUFFER)
#define TP_SHADOW_PCF_RADIUS 1         // PCF kernel (2r + 1)^2 texels: 3 x 3, box weights
#define TP_SHADOW_NORMAL_OFFSET 1.5f   // receiver moved along its normal by this many texels
#define TP_SHADOW_DEPTH_BIAS 1.0f      // and compared this many texel footprints nearer
#define TP_SHADOW_FACES_POINT 6u
#define TP_SHADOW_FACES_SPOT 1u
// Specialization constant: the sampled map is one light's (the `local` rects), not the atlas.
#define TP_SPEC_SHADOW_LOCAL 5
// 1: the atlas is read from TP_BINDING_SHADOW_DEPTH, the float bits the compute rasterizer wrote
// (--shadow-raster compute, maps every frame), rows of TP_SPEC_SHADOW_ATLAS_WIDTH texels: the same
// values the D32 atlas would hold after a copy, without the copy. 0: the map's texels.
#define TP_SPEC_SHADOW_BUFFER 31
#define TP_SPEC_SHADOW_ATLAS_WIDTH 32

#ifndef TP_GLSL
namespace tp::gpu {
#endif

TP_STRUCT(ShadowFace) {
    mat4 lightProj; // light-relative position -> the face's clip space (w: distance on its axis)
    uvec4 atlas;    // x, y: the face's first texel in the atlas; z: edge in texels; w: light index
    uvec4 local;    // x, y: the first texel in its light's own map (3 x 2 faces); z: edge; w: face
    vec4 params;    // x: texel footprint at distance 1 (2 tan(fov/2) / edge); y: near; z: its
                    // light's face count (6 or 1); w: unused
};

#ifndef TP_GLSL
static_assert(sizeof(ShadowFace) == 64 + 3 * 16);
} // namespace tp::gpu
#endif
#endif
