#include "core/render/camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace tp {

glm::mat4 viewMatrix(const Camera& camera) {
    glm::vec3 forward = camera.target - camera.position;
    glm::vec3 up = camera.up;
    // A camera looking straight along its up vector would give a singular basis.
    if (glm::length(glm::cross(forward, up)) < 1e-6f * glm::length(forward))
        up = std::abs(forward.y) > 0.9f * glm::length(forward) ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    return glm::lookAt(camera.position, camera.target, up);
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
