#include "core/camera/pixel_position.h"

#include "core/camera/camera.h"
#include "include/sample_locations.h"

namespace tp {

glm::dmat4 inverseShadingViewProjection(const Camera& camera, uint32_t width, uint32_t height) {
    const double aspect = double(width) / double(height);
    return glm::inverse(
        glm::dmat4(reverseZPerspective(camera.yfov, float(aspect), camera.znear, camera.zfar)) *
        viewRotation(camera));
}

glm::dvec3 pixelCentrePosition(const glm::dmat4& inverse, uint32_t width, uint32_t height,
                               uint32_t x, uint32_t y, double depth) {
    return framebufferPosition(inverse, width, height, x + 0.5, y + 0.5, depth);
}

glm::dvec3 framebufferPosition(const glm::dmat4& inverse, uint32_t width, uint32_t height,
                               double fx, double fy, double depth) {
    // Clip-space Y is up; the viewport flips it, so row 0 is the top row.
    const glm::dvec4 ndc(fx / width * 2.0 - 1.0, 1.0 - fy / height * 2.0, depth, 1.0);
    const glm::dvec4 h = inverse * ndc;
    return glm::dvec3(h) / h.w;
}

glm::dvec2 standardSampleOffset(uint32_t samples, uint32_t s) {
    static const glm::dvec2 p2[] = {TP_SAMPLE_LOCATIONS_2(glm::dvec2)},
                            p4[] = {TP_SAMPLE_LOCATIONS_4(glm::dvec2)},
                            p8[] = {TP_SAMPLE_LOCATIONS_8(glm::dvec2)};
    const glm::dvec2* p = samples == 2 ? p2 : samples == 4 ? p4 : samples == 8 ? p8 : nullptr;
    if (!p || s >= samples) return {0.5, 0.5};
    return p[s];
}

} // namespace tp
