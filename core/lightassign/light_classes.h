#pragma once
// Light classes of light assignment: directional lights reach every tile and are never
// culled; point and spot lights (local) are culled per tile.
#include <cstdint>
#include <vector>

#include "include/shared.h"

namespace tp::la {

struct LightClasses {
    std::vector<uint32_t> directional; // indices into the light array, ascending
    std::vector<uint32_t> local;       // point and spot lights, ascending
};

LightClasses classifyLights(const std::vector<gpu::LightGpu>& lights);

} // namespace tp::la
