#pragma once
// Constants more than one file needs, defined once (a file-local copy in each would collide in
// a unity build, and could drift).
#include <numbers>

namespace tp {

inline constexpr float kPi = std::numbers::pi_v<float>;

} // namespace tp
