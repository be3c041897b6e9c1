#include "multipass_forward/mp_settings.h"

#include <algorithm>

namespace tp::mp {
namespace {

const ChoiceKnob<Accum>& accumKnob() {
    static const ChoiceKnob<Accum> k{"accum",
                                     {{Accum::Fp32, "fp32"}, {Accum::Fp16, "fp16"}},
                                     "Multipass forward accumulation target precision"};
    return k;
}

const ChoiceKnob<LightLists>& lightListsKnob() {
    static const ChoiceKnob<LightLists> k{
        "light-draws",
        {{LightLists::Gpu, "gpu"}, {LightLists::GpuBlended, "gpu-blended"}, {LightLists::Cpu, "cpu"}},
        "Multipass forward per-light draw lists: gpu (a compute pass writes each light's "
        "indirect draws of opaque and masked meshes every frame; the blended draws' lights are "
        "planned and recorded per view, each scissored to its light), gpu-blended (with "
        "--blended-lights under the blended draws' light draws and resets too: a new view "
        "re-plans nothing per light, but each light draw rasterizes its whole mesh and discards "
        "outside the light's rectangle, a slower frame: docs/multipass_forward.md; blended "
        "lights stay on the CPU with --shadows or without dualSrcBlend) or cpu (built on the "
        "CPU for each view, one recorded draw per light and mesh)"};
    return k;
}

} // namespace

const ChoiceKnob<BlendedLights>& blendedLightsKnob() {
    static const ChoiceKnob<BlendedLights> k{
        "blended-lights",
        {{BlendedLights::Under, "under"},
         {BlendedLights::Additive, "additive"},
         {BlendedLights::OnePass, "one-pass"}},
        "Multipass forward lights on blended surfaces: under (a pass per light, composited under "
        "the draw's own nearer layers: exact where a mesh overlaps itself), additive (the textbook "
        "pass per light, alpha * light added: too bright by a_near * a_far * L_far where it does) "
        "or "
        "one-pass (every light in the blended draw's one shading pass, as forward engines light "
        "transparent objects)"};
    return k;
}

KnobSchema knobs() {
    return {msaaShadingKnob().knob(), accumKnob().knob(), blendedLightsKnob().knob(),
            cullGeometryKnob().knob(), lightListsKnob().knob(), shadowRasterKnob().knob()};
}

double blendedLightsPerFragment(BlendedLights mode, double directional, double lights) {
    switch (mode) {
    case BlendedLights::OnePass:
        return lights; // every light of the scene (one_pass.frag)
    case BlendedLights::Additive:
        return std::min(1.0, directional); // F = C + L
    case BlendedLights::Under:
        break;
    }
    return std::min(0.5, directional);
}

double blendedSamplingShare(BlendedLights mode) {
    return mode == BlendedLights::Under ? 0.5 : 1.0;
}

Settings readSettings(const RenderSettings& s) {
    return {s.width,
            s.height,
            readSampling(s),
            accumKnob().in(s),
            blendedLightsKnob().in(s),
            cullGeometryKnob().in(s),
            lightListsKnob().in(s),
            shadowRasterKnob().in(s)};
}

} // namespace tp::mp
