#include "core/lightassign/light_classes.h"

namespace tp::la {

LightClasses classifyLights(const std::vector<gpu::LightGpu>& lights) {
    LightClasses c;
    for (uint32_t i = 0; i < lights.size(); ++i)
        (lights[i].type == TP_LIGHT_DIRECTIONAL ? c.directional : c.local).push_back(i);
    return c;
}

} // namespace tp::la
