// Forward+ as the rest of the program sees it: its name, its knobs, its precision model for
// `triptych stress`. This file is the only place outside forwardplus/ that needs to change
// when Forward+ gains a knob: nowhere.
#include "core/renderer/msaa_knob.h"
#include "core/renderer/renderer.h"
#include "forwardplus/forwardplus_renderer.h"
#include "forwardplus/fp_settings.h"

namespace tp {
namespace {

// Colour stored in RGBA16F (--hdr fp16, and auto): one rounding per store (the sample, then
// the resolve). --hdr fp32: RGBA32F holds the fp32 sum as it is, no storage term.
// Blended layers: each blended into the hdr target (per sample under MSAA) once, with all its
// lights, and stored there in its format.
void forwardPlusErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    const bool fp16 = fp::readSettings(in.settings).hdr == HdrStorage::Fp16;
    if (fp16) addFp16StorageTerm(b, in.settings.msaa > 1 ? 2 : 1, "sample, resolve");
    addPixelRateErrorTerm(b, in);
    addBlendedLayersTerm(b, in, 1, fp16, "each blended with all its lights in one draw");
}

// A case that crowds one tile must find Forward+'s list holding all of them (the compact and
// linked layouts size their lists from a conservative bound; 'fixed' caps them, and counts
// the drops instead).
std::vector<stress::CounterAtLeast> forwardPlusStressed(const ErrorModelInput& in) {
    const stress::StressCase& c = in.stressCase;
    if (c.lightsInOneTile <= 4096 || fp::readSettings(in.settings).lists == fp::ListLayout::Fixed)
        return {};
    return {{"lights_per_tile_max", 4097,
             "a tile list must hold more than 4,096 lights (the case puts " +
                 std::to_string(c.lightsInOneTile) + " in one tile)"}};
}

const RendererRegistration registration{
    {"forwardplus", "Forward+: depth prepass, per-tile light lists in compute, forward shading",
     createForwardPlusRenderer, 10, fp::knobs(), forwardPlusErrorModel, forwardPlusStressed}};

} // namespace
} // namespace tp
