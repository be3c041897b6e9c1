// Forward+ as the rest of the program sees it: its name, its knobs, its precision model for
// `triptych stress`. This file is the only place outside forwardplus/ that needs to change
// when Forward+ gains a knob: nowhere.
#include "core/lightassign/assign_knob.h"
#include "core/lightassign/bin_knob.h"
#include "core/lightassign/cull_knob.h"
#include "core/lightassign/loop_knob.h"
#include "core/lightassign/tile_knob.h"
#include "core/render/msaa_knob.h"
#include "core/render/renderer.h"
#include "forwardplus/forwardplus_renderer.h"

namespace tp {
namespace {

KnobSchema forwardPlusKnobs() {
    return {la::tileSizeKnob(),
            la::lightCullKnob(),
            la::lightBinKnob(),
            la::lightAssignKnob(),
            la::slicesKnob(),
            la::lightLoopKnob(),
            msaaShadingKnob(),
            Knob::choice("light-lists", {"compact", "fixed", "linked"},
                         "Forward+ light-list layout: compact (count, prefix sum, fill; never drops), fixed (fixed "
                         "capacity per tile; drops are counted), linked (per-tile linked lists)"),
            Knob::integer("tile-capacity", 1, 65536, 256, "Light slots per tile of the 'fixed' light-list layout")
                .fixed(),
            // Same lists either way: only where the time and the 16 bytes per light go.
            Knob::choice("light-spheres", {"auto", "pass", "inline"},
                         "Each light's view-space sphere for the culling: pass (once per light in the "
                         "light_spheres pass, 16 bytes per light), inline (per candidate in the culling) or auto "
                         "(pass on a CPU device such as lavapipe, inline on a GPU)"),
            // Same bytes either way: only who does the work.
            Knob::choice("cull-by", {"auto", "invocation", "subgroup"},
                         "Who culls a tile in light_culling: invocation (one thread walks the tile's candidates; "
                         "cheapest on a CPU device such as lavapipe), subgroup (one subgroup per tile, a candidate "
                         "per lane, survivors placed in order by a ballot: a GPU runs tiles x lanes threads) or auto "
                         "(invocation on a CPU device, subgroup on a GPU that supports it); the same lists either "
                         "way")};
}

// Colour is stored in RGBA16F: one rounding per store (the sample, then the resolve).
void forwardPlusErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    addFp16StorageTerm(b, in.settings.msaa > 1 ? 2 : 1, "sample, resolve");
    addPixelRateErrorTerm(b, in);
}

// A case that crowds one tile must find Forward+'s list holding all of them (the compact and
// linked layouts size their lists from a conservative bound; 'fixed' caps them, and counts
// the drops instead).
std::vector<stress::CounterAtLeast> forwardPlusStressed(const ErrorModelInput& in) {
    const stress::StressCase& c = in.stressCase;
    if (c.lightsInOneTile <= 4096 || in.settings.text("light-lists") == "fixed") return {};
    return {{"lights_per_tile_max", 4097, "a tile list must hold more than 4,096 lights (the case puts " +
                                              std::to_string(c.lightsInOneTile) + " in one tile)"}};
}

const RendererRegistration registration{{"forwardplus",
                                         "Forward+: depth prepass, per-tile light lists in compute, forward shading",
                                         createForwardPlusRenderer, 10, forwardPlusKnobs(), forwardPlusErrorModel,
                                         forwardPlusStressed}};

} // namespace
} // namespace tp
