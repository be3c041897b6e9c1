// Multipass forward as the rest of the program sees it: its name, its knobs, its precision
// model for `triptych stress`.
#include "core/render/msaa_knob.h"
#include "core/render/renderer.h"
#include "multipass_forward/multipass_renderer.h"

namespace tp {
namespace {

KnobSchema multipassKnobs() {
    return {msaaShadingKnob(),
            Knob::choice("accum", {"fp32", "fp16"}, "Multipass forward accumulation target precision"),
            Knob::choice("blended-lights", {"under", "additive", "one-pass"},
                         "Multipass forward lights on blended surfaces: under (a pass per light, composited under "
                         "the draw's own nearer layers: exact where a mesh overlaps itself), additive (the textbook "
                         "pass per light, alpha * light added: too bright by a_near * a_far * L_far where it does) or "
                         "one-pass (every light in the blended draw's one shading pass, as forward engines light "
                         "transparent objects)")};
}

void multipassErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    const size_t lights = in.scene.lights.size();
    if (in.settings.text("accum") == "fp16")
        b.terms.push_back({"fp16 accumulation", double(lights + 2) * kHalfUlp16, double(lights + 2) * 6e-8,
                           "one fp16 rounding per additive pass"});
    else
        b.terms.push_back({"fp32 accumulation", 0, 0, "each additive pass rounds in fp32: inside the summation term"});
    addPixelRateErrorTerm(b, in);
}

const RendererRegistration registration{{"multipass_forward", "one additive pass per light after a depth prepass",
                                         createMultipassForwardRenderer, 30, multipassKnobs(), multipassErrorModel,
                                         {}}};

} // namespace
} // namespace tp
