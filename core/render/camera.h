#pragma once
// Camera matrices: right-handed view, reverse-Z perspective (depth 1 at the near plane,
// 0 at the far plane or at infinity), clip-space Y up (the viewport flips it).
#include <glm/glm.hpp>

#include "core/scene/scene.h"

namespace tp {

glm::mat4 viewMatrix(const Camera& camera);
glm::mat4 reverseZPerspective(float yfov, float aspect, float znear, float zfar);

} // namespace tp
