#pragma once
// The pixel inspector's "lights of this pixel": the lights whose range (and, for a spot, cone)
// reaches the surface the pixel shows, found on the CPU from the read-back depth. These are the
// lights every pipeline must shade there; a culled light list that misses one is a bug, one
// that holds more is the tile's conservatism.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "core/image/image.h"
#include "core/scene/scene.h"

namespace tp::view {

// World position of the surface at pixel (x, y) (reverse-Z depth, 0 = nothing there).
std::optional<glm::dvec3> surfaceAt(const Camera& camera, const ImageR32& depth, uint32_t x,
                                    uint32_t y);
// Indices into `lights` of those that reach `p`.
std::vector<uint32_t> lightsReaching(const std::vector<Light>& lights, const glm::dvec3& p);

} // namespace tp::view
