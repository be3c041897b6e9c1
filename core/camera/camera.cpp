#include "core/camera/camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace tp {

glm::dmat4 viewRotation(const Camera& camera) {
    glm::dvec3 forward = glm::dvec3(camera.target) - glm::dvec3(camera.position);
    glm::dvec3 up = camera.up;
    // A camera looking straight along its up vector would give a singular basis.
    if (glm::length(glm::cross(forward, up)) < 1e-6 * glm::length(forward))
        up = std::abs(forward.y) > 0.9 * glm::length(forward) ? glm::dvec3(0, 0, 1)
                                                              : glm::dvec3(0, 1, 0);
    return glm::lookAt(glm::dvec3(0.0), forward, up);
}

glm::dmat4 viewMatrixWorld(const Camera& camera) {
    return glm::translate(viewRotation(camera), -glm::dvec3(camera.position));
}

glm::mat4 viewMatrix(const Camera& camera) {
    return glm::mat4(viewMatrixWorld(camera));
}

glm::mat4 reverseZPerspective(float yfov, float aspect, float znear, float zfar) {
    float f = 1.0f / std::tan(yfov * 0.5f);
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][3] = -1.0f;
    if (zfar <= 0.0f) { // infinite far plane: depth = znear / -z_view
        m[3][2] = znear;
    } else {
        m[2][2] = znear / (zfar - znear);
        m[3][2] = znear * zfar / (zfar - znear);
    }
    return m;
}

} // namespace tp
