#include "viewer/camera_control.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace tp::view {
namespace {

// Pitch stops short of the up axis: the view matrix is undefined when looking along `up`.
constexpr float kMaxPitchCos = 0.995f;

glm::vec3 rotated(glm::vec3 v, glm::vec3 axis, float degrees) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(axis)) *
                     glm::vec4(v, 0.0f));
}

// Yaw about `up`, then pitch about the right axis, refusing a pitch that would pass the pole.
glm::vec3 turn(glm::vec3 dir, glm::vec3 up, float yaw, float pitch) {
    dir = rotated(dir, up, yaw);
    glm::vec3 right = glm::cross(dir, up);
    if (glm::length(right) < 1e-6f) return dir;
    glm::vec3 pitched = rotated(dir, right, pitch);
    float c = std::abs(glm::dot(glm::normalize(pitched), glm::normalize(up)));
    return c < kMaxPitchCos ? pitched : dir;
}

} // namespace

float moveStep(const Camera& c) {
    return std::max(glm::length(c.target - c.position) / 20.0f, 1e-3f);
}

void flyMove(Camera& c, float forward, float right, float up) {
    glm::vec3 f = c.target - c.position;
    if (glm::length(f) < 1e-9f) return;
    f = glm::normalize(f);
    glm::vec3 r = glm::normalize(glm::cross(f, c.up));
    glm::vec3 u = glm::normalize(c.up);
    glm::vec3 d = f * forward + r * right + u * up;
    c.position += d;
    c.target += d;
}

void flyTurn(Camera& c, float yawDegrees, float pitchDegrees) {
    glm::vec3 dir = c.target - c.position;
    c.target = c.position + turn(dir, c.up, -yawDegrees, -pitchDegrees);
}

void orbit(Camera& c, float yawDegrees, float pitchDegrees) {
    glm::vec3 arm = c.position - c.target;
    c.position = c.target + turn(arm, c.up, -yawDegrees, pitchDegrees);
}

void dolly(Camera& c, float factor) {
    glm::vec3 arm = c.position - c.target;
    float keep = std::clamp(1.0f - factor, 0.01f, 100.0f);
    c.position = c.target + arm * keep;
}

} // namespace tp::view
