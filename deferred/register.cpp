// G-buffer deferred as the rest of the program sees it: its name, its knobs, its precision
// model for `triptych stress` (deferred/error_model.cpp).
#include "core/renderer/renderer.h"
#include "deferred/def_settings.h"
#include "deferred/deferred_renderer.h"
#include "deferred/deferred_shared.h"
#include "deferred/error_model.h"

namespace tp {
namespace {

std::vector<stress::CounterAtLeast> deferredStressed(const ErrorModelInput& in) {
    const stress::StressCase& c = in.stressCase;
    if (def::readSettings(in.settings).lighting != def::Lighting::Tiled ||
        c.lightsInOneTile <= TP_TL_TILE_LIGHT_CAPACITY)
        return {};
    return {{"tiles_over_shared_capacity", 1,
             "the 4,096-light shared list must overflow (the case puts " +
                 std::to_string(c.lightsInOneTile) + " in one tile)"}};
}

const RendererRegistration registration{
    {"deferred", "G-buffer deferred: tiled compute lighting, hybrid forward pass for blended",
     createDeferredRenderer, 20, def::knobs(), deferredErrorModel, deferredStressed}};

} // namespace
} // namespace tp
