// Multipass forward as the rest of the program sees it: its name, its knobs, its precision
// model for `triptych stress`.
#include "core/renderer/msaa_knob.h"
#include "core/renderer/renderer.h"
#include "multipass_forward/mp_settings.h"
#include "multipass_forward/multipass_renderer.h"

namespace tp {
namespace {

void multipassErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    const size_t lights = in.scene.lights.size();
    if (mp::readSettings(in.settings).accum == mp::Accum::Fp16)
        b.terms.push_back({"fp16 accumulation", double(lights + 2) * kHalfUlp16,
                           double(lights + 2) * 6e-8, "one fp16 rounding per additive pass"});
    else
        b.terms.push_back({"fp32 accumulation", 0, 0,
                           "each additive pass rounds in fp32: inside the summation term"});
    addPixelRateErrorTerm(b, in);
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
