// Multipass forward as the rest of the program sees it: its name, its knobs, its precision
// model for `triptych stress`.
#include "core/renderer/msaa_knob.h"
#include "core/renderer/renderer.h"
#include "multipass_forward/mp_settings.h"
#include "multipass_forward/multipass_renderer.h"
#include "multipass_forward/multipass_shared.h"

namespace tp {
namespace {

// A blended layer's blends: its composite (ambient, emission, the base pass's directional
// lights), then under `under` and `additive` one blend per light drawn onto it in a pass of its
// own (every local light that reaches it, and the directional lights beyond the base pass's
// TP_MP_MAX_BASE_DIRECTIONAL, drawn full-screen); `one-pass` shades every light in the composite.
uint32_t blendsPerBlendedLayer(const ErrorModelInput& in, mp::BlendedLights mode) {
    if (mode == mp::BlendedLights::OnePass) return 1;
    uint32_t local = 0, directional = 0;
    for (const Light& l : in.scene.lights)
        (l.type == LightType::Directional ? directional : local) += 1;
    return 1 + local + (directional > TP_MP_MAX_BASE_DIRECTIONAL
                            ? directional - TP_MP_MAX_BASE_DIRECTIONAL
                            : 0);
}

void multipassErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    const size_t lights = in.scene.lights.size();
    const mp::Settings s = mp::readSettings(in.settings);
    if (s.accum == mp::Accum::Fp16)
        b.terms.push_back({"fp16 accumulation", double(lights + 2) * kHalfUlp16,
                           double(lights + 2) * 6e-8, "one fp16 rounding per additive pass"});
    else
        b.terms.push_back({"fp32 accumulation", 0, 0,
                           "each additive pass rounds in fp32: inside the summation term"});
    addPixelRateErrorTerm(b, in);
    addBlendedLayersTerm(b, in, blendsPerBlendedLayer(in, s.blendedLights),
                         s.accum == mp::Accum::Fp16,
                         s.blendedLights == mp::BlendedLights::OnePass
                             ? "each shaded with every light in its one composite"
                             : "each a composite and one blend per light drawn onto it");
}

const RendererRegistration registration{{"multipass_forward",
                                         "one additive pass per light after a depth prepass",
                                         createMultipassForwardRenderer,
                                         30,
                                         mp::knobs(),
                                         multipassErrorModel,
                                         {}}};

} // namespace
} // namespace tp
