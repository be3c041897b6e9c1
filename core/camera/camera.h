#pragma once
// Camera matrices: right-handed view, reverse-Z perspective (depth 1 at the near plane,
// 0 at the far plane or at infinity), clip-space Y up (the viewport flips it).
//
// Shading is camera-relative (docs/shading.md, "Camera-relative shading"): the GPU gets the
// rotation-only view (the eye at the origin) and positions minus the eye, so nothing it
// computes carries the eye's magnitude; the world-space view stays for CPU code that works
// in world coordinates.
#include <glm/glm.hpp>

#include "core/scene/scene.h"

namespace tp {

// The view matrix with the eye at the origin (rotation only), in double.
glm::dmat4 viewRotation(const Camera& camera);
// The world-space view matrix, rotation * translate(-eye) composed in double.
glm::dmat4 viewMatrixWorld(const Camera& camera);
glm::mat4 viewMatrix(const Camera& camera);
glm::mat4 reverseZPerspective(float yfov, float aspect, float znear, float zfar);

} // namespace tp
