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

// A spot whose cone has no falloff to speak of: cos(inner) - cos(outer) at most the GPU's
// clamp (kHardSpotSpread, scene_gpu.cpp: spotScale = 1 / max(1e-4, cos inner - cos outer)),
// outer > 0 (a zero cone lights nothing at all). Its ramp is 1e-4 wide in the cosine, far
// thinner than a pixel: the edge is a step.
constexpr double kHardSpotSpread = 1e-4;
bool isHardSpot(const Light& light);

// Per pixel, what a hard spot's edge can change there (docs/stress.md, "Hard spot edges"): a
// pixel whose shaded points may lie on both sides of the cone, or inside its ramp, can be lit
// by the spot in one image and not in another (points a rounding apart, or a position error
// apart, or another sample under MSAA). Such a pixel gets the spot's whole reflected light
// (reflectedLightBounds of the spot alone); every other pixel 0, for it sees the spot's cone
// factor the same (0 or 1) in every image. "May straddle": a ball of one pixel width at the
// point's view depth (the samples' and the pipelines' points all lie within it at 1x) around the
// reference's point meets the ramp widened by 1e-5 in the cosine (the fp32 rounding of the
// cosine against the axis); under MSAA (samples > 1) the largest of the 3x3 neighbourhood (a
// sample's surface is the centre's of this pixel or of a neighbour). Empty (0 x 0) when the
// scene has no hard spot.
ImageR32 hardSpotEdgeAllowance(const Scene& scene, const ImageR32& depth, uint32_t samples);

// Each pixel the largest value of its 3x3 neighbourhood (an MSAA pixel's samples may lie on
// the surfaces of its neighbours' sample 0).
ImageR32 maxOver3x3(const ImageR32& a);

} // namespace tp
