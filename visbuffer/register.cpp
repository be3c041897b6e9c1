// The visibility buffer as the rest of the program sees it: its name, its knobs, its
// precision model for `triptych stress` (visbuffer/error_model.cpp).
#include "core/renderer/renderer.h"
#include "passes/tiled_lighting.h"
#include "visbuffer/error_model.h"
#include "visbuffer/vis_settings.h"
#include "visbuffer/visbuffer_renderer.h"

namespace tp {
namespace {

// A case that crowds one tile must overflow the tiled pass's shared list (its lights then
// come in several batches, none dropped), as for deferred.
std::vector<stress::CounterAtLeast> visbufferStressed(const ErrorModelInput& in) {
    const stress::StressCase& c = in.stressCase;
    if (c.lightsInOneTile <= TP_TL_TILE_LIGHT_CAPACITY) return {};
    return {{"tiles_over_shared_capacity", 1,
             "the 4,096-light shared list must overflow (the case puts " +
                 std::to_string(c.lightsInOneTile) + " in one tile)"}};
}

const RendererRegistration registration{
    {"visbuffer",
     "visibility buffer: depth + triangle id per sample, material and tiled lighting in compute",
     createVisbufferRenderer, 25, vis::knobs(), visbufferErrorModel, visbufferStressed}};

} // namespace
} // namespace tp
