#pragma once
// The visibility buffer's texture level-of-detail error, per pixel (docs/visbuffer.md,
// "Texture level of detail").
//
// The resolve samples textures with textureGrad from the analytic derivatives of the
// barycentrics at the shaded location; the reference's fragment stage samples with the
// hardware's derivatives, finite differences over its 2x2 quad (fine or coarse, the device's
// choice), and may take one level of detail per quad. On a plane, an attribute's screen
// derivative scales as 1/q^2 with q = 1/w affine in screen space, so the two differ by the
// ratio of q over the quad: |delta lambda| <= 3 log2(q_max / q_min) (one factor for the finite
// difference, two for the row or pixel of the quad it is taken at) plus 2^-8 for the level
// arithmetic, capped by the textures' level span. q's gradient comes from the reference's
// depth (the nearer neighbour on each axis, as the position allowance reads the surface).
//
// A trilinear sample is piecewise linear in the level, each level a convex combination of
// texels, so it moves by at most |delta lambda| times the texture's channel range. Radiance
// is affine and non-decreasing in base colour and affine in metallic, moves by at most 6 dr/r
// relatively with roughness, by its Lipschitz bound (twice: light and view) with the normal's
// angle, and one for one with emission; the ambient term (ambient * base * (1 - metallic) *
// occlusion) by ambient times the change of base colour, metallic or occlusion. Each with the
// largest factor over the scene's textured materials (position_allowance.h's light bounds).
#include "core/image/image.h"
#include "core/scene/scene.h"

namespace tp::vis {

// HDR radiance allowance per pixel for an image of depth.width x depth.height rendered with
// the scene's camera; all 0 when no material is textured. With the reference's image, the
// base colour's part is relative to the reference's radiance at the pixel: radiance is
// A * base + B with A, B >= 0, so A <= R / base and a texel change moves it by at most
// R * dt / t (the factor and vertex colour cancel), t the texture's darkest texel.
ImageR32 textureLodAllowance(const Scene& scene, const ImageR32& depth,
                             const ImageRGBA* reference = nullptr);

// The bound on |delta lambda| per pixel (0 where there is no geometry), capped at `levelSpan`:
// what textureLodAllowance multiplies by the radiance's sensitivity.
ImageR32 levelChangeBounds(const Scene& scene, const ImageR32& depth, uint32_t levelSpan);

} // namespace tp::vis
