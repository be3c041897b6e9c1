#pragma once
// The position error next to lights, per pixel, of a pipeline that shades a point up to a
// snapped vertex grid away from the reference's (deferred: from depth; the visibility buffer:
// the exact hit against unsnapped vertices) (docs/stress.md,
// "Position from depth next to a light").
//
// Deferred shades the point on the ray through the pixel centre at the depth the rasterizer
// stored. A rasterizer snaps vertices to a grid of 2^-subPixelBits pixel before it sets up
// the depth plane, so that depth is the depth of the surface point up to
// eps = sqrt(2) * 2^-(subPixelBits + 1) pixel widths away across the view ray: the
// reconstructed point lies up to eps (at its view depth) off the surface the reference
// shades. Far from lights this is a tiny relative change; next to a light it is a change of
// the light direction and distance of eps / d, large when a light hugs a surface. The
// allowance is, per pixel, eps times a bound on the gradient of every light term reaching
// it: inverse-square falloff, range window, spot cone and a sampled Lipschitz bound of the
// BRDF over the scene's materials.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/image/image.h"
#include "core/scene/scene.h"

namespace tp {

// The per-sample lateral displacement bound eps, in units of the pixel width at the
// sample's view depth.
double snappedPositionPixels(uint32_t subPixelBits);

// Largest brdfCos and its Lipschitz constant with respect to the light direction and the
// view direction (per radian), over the scene's materials (base colour at its largest
// channel, 1 where textured), sampled; both times 1.25 for the sampling's gaps. One per
// 2-degree bucket of the angle between the view direction and the normal (0 to 90).
struct BrdfLimits {
    double maxValue = 0;
    double lipschitz = 0;
};
std::vector<BrdfLimits> brdfLimits(const Scene& scene);

// HDR radiance allowance per pixel for an image of depth.width x depth.height rendered
// with the scene's camera: 0 where the pixel has no geometry; directional lights add their
// (small) view-direction term everywhere; +Inf where a local light may lie within 1.01 eps of
// the shaded point (nothing is bounded there).
// samples > 1: also at each standard sample location of the pixel, on the plane its
// neighbours span (the largest), for a pipeline that shades each sample at its own point.
ImageR32 positionFromDepthAllowance(const Scene& scene, const ImageR32& depth,
                                    uint32_t subPixelBits, uint32_t samples = 1);

// Camera-relative position of every pixel centre from a reverse-Z depth (NaN: sky).
std::vector<glm::dvec3> pixelPositions(const Camera& cam, const ImageR32& depth);

// Per pixel, bounds on the light the surface there reflects toward the eye, from the same
// BRDF limits: `value` >= the sum over lights of intensity * window / d^2 * brdfCos with a
// base colour of 1 (so, brdfCos being affine and non-decreasing in the base colour and affine
// in metallic, also a bound on the change per unit of either), `lipschitz` >= the same sum
// with brdfCos's Lipschitz constant per radian of light or view direction. 0 where there is
// no geometry.
struct ReflectedLightBounds {
    ImageR32 value, lipschitz;
};
ReflectedLightBounds reflectedLightBounds(const Scene& scene, const ImageR32& depth);

} // namespace tp
