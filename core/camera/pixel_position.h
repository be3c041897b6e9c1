#pragma once
// From a pixel centre and its reverse-Z depth back to a position, on the CPU in double: what
// the GPU reconstructs (shaders/deferred/gbuffer_read.glsl, reconstructPosition), for code that
// reasons about the surface under a pixel (deferred's stress allowance, the viewer's inspector).
#include <cstdint>

#include <glm/glm.hpp>

#include "core/scene/scene.h"

namespace tp {

// inverse(projection * rotation-only view) for a width x height image: NDC (x, y, depth) to the
// camera-relative position (world minus eye).
glm::dmat4 inverseShadingViewProjection(const Camera& camera, uint32_t width, uint32_t height);

// Camera-relative position of the centre of pixel (x, y) (row 0 at the top) at reverse-Z
// `depth`, with `inverse` from inverseShadingViewProjection.
glm::dvec3 pixelCentrePosition(const glm::dmat4& inverse, uint32_t width, uint32_t height,
                               uint32_t x, uint32_t y, double depth);
// The same at framebuffer location (fx, fy) in pixels (pixel (x, y)'s centre is x + 0.5, y + 0.5).
glm::dvec3 framebufferPosition(const glm::dmat4& inverse, uint32_t width, uint32_t height,
                               double fx, double fy, double depth);

// Sample s of `samples` (2, 4 or 8; else the centre) at Vulkan's standard sample locations,
// from the pixel's corner: the table shaders/include/sample_locations.glsl holds.
glm::dvec2 standardSampleOffset(uint32_t samples, uint32_t s);

} // namespace tp
