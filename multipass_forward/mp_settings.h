#pragma once
// Multipass forward's knobs and the typed settings its passes read (register.cpp builds the
// schema from the same declarations).
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/knobs.h"
#include "core/renderer/msaa_knob.h"
#include "core/renderer/shadow_raster_knob.h"

namespace tp::mp {

enum class Accum { Fp32, Fp16 };                       // --accum
enum class BlendedLights { Under, Additive, OnePass }; // --blended-lights
enum class LightLists { Gpu, GpuBlended, Cpu };        // --light-draws

struct Settings {
    uint32_t width = 0, height = 0;
    Sampling sampling;
    Accum accum = Accum::Fp32;
    BlendedLights blendedLights = BlendedLights::Under;
    CullGeometry cullGeometry = CullGeometry::None; // --cull-geometry: prepass, base, light passes
    LightLists lightLists = LightLists::Gpu; // who selects each light's opaque and masked draws
    ShadowRaster shadowRaster = ShadowRaster::Hardware; // --shadow-raster (one light's map: hardware)
};

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);
const ChoiceKnob<BlendedLights>& blendedLightsKnob();

// The blended pass's counted work per fragment, lower bounds (docs/efficiency.md): its fragments
// are composites (C: the directional lights and the material), light draws (L: one light and the
// material) and, compositing under, as many transmittance resets (R = L at the pixel rate, R <= L
// per sample: the same triangles, scissor and depth test) that evaluate and sample nothing. With
// F = C + L + R, L >= (F - C) / 2: at least min(1/2, directional) evaluations a fragment, and half
// of the fragments sample the material. One-pass: every light, every fragment.
double blendedLightsPerFragment(BlendedLights mode, double directional, double lights);
double blendedSamplingShare(BlendedLights mode);

} // namespace tp::mp
