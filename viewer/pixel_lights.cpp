#include "viewer/pixel_lights.h"

#include <cmath>

#include "core/camera/pixel_position.h"

namespace tp::view {

std::optional<glm::dvec3> surfaceAt(const Camera& camera, const ImageR32& depth, uint32_t x,
                                    uint32_t y) {
    if (x >= depth.width || y >= depth.height) return std::nullopt;
    const double d = depth.r[size_t(y) * depth.width + x];
    if (!(d > 0.0)) return std::nullopt; // the far plane / sky
    const glm::dmat4 inverse = inverseShadingViewProjection(camera, depth.width, depth.height);
    const glm::dvec3 relative = pixelCentrePosition(inverse, depth.width, depth.height, x, y, d);
    if (!std::isfinite(relative.x + relative.y + relative.z)) return std::nullopt;
    return relative + glm::dvec3(camera.position); // world space, as the lights are
}

std::vector<uint32_t> lightsReaching(const std::vector<Light>& lights, const glm::dvec3& p) {
    std::vector<uint32_t> out;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        if (l.type == LightType::Directional) {
            out.push_back(i);
            continue;
        }
        glm::dvec3 toSurface = p - glm::dvec3(l.position);
        double distance = glm::length(toSurface);
        if (distance >= l.range) continue; // the window is exactly zero at the range
        if (l.type == LightType::Spot && distance > 0.0) {
            double c = glm::dot(toSurface / distance, glm::normalize(glm::dvec3(l.direction)));
            if (c <= std::cos(double(l.outerConeAngle))) continue;
        }
        out.push_back(i);
    }
    return out;
}

} // namespace tp::view
