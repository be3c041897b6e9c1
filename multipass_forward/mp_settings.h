#pragma once
// Multipass forward's knobs and the typed settings its passes read (register.cpp builds the
// schema from the same declarations).
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/knobs.h"
#include "core/renderer/msaa_knob.h"

namespace tp::mp {

enum class Accum { Fp32, Fp16 };                       // --accum
enum class BlendedLights { Under, Additive, OnePass }; // --blended-lights

struct Settings {
    uint32_t width = 0, height = 0;
    Sampling sampling;
    Accum accum = Accum::Fp32;
    BlendedLights blendedLights = BlendedLights::Under;
    CullGeometry cullGeometry = CullGeometry::None; // --cull-geometry: prepass, base, light passes
};

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);
const ChoiceKnob<BlendedLights>& blendedLightsKnob();

} // namespace tp::mp
