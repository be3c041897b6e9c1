#include "core/render/pixel_position.h"

#include "core/render/camera.h"

namespace tp {

glm::dmat4 inverseShadingViewProjection(const Camera& camera, uint32_t width, uint32_t height) {
    const double aspect = double(width) / double(height);
    return glm::inverse(
        glm::dmat4(reverseZPerspective(camera.yfov, float(aspect), camera.znear, camera.zfar)) *
        viewRotation(camera));
}

glm::dvec3 pixelCentrePosition(const glm::dmat4& inverse, uint32_t width, uint32_t height,
                               uint32_t x, uint32_t y, double depth) {
    // Clip-space Y is up; the viewport flips it, so row 0 is the top row.
    const glm::dvec4 ndc((x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0, depth, 1.0);
    const glm::dvec4 h = inverse * ndc;
    return glm::dvec3(h) / h.w;
}

} // namespace tp
