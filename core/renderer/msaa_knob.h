#pragma once
// The MSAA shading-rate knob of every pipeline (`--msaa-shading pixel|sample`). Declared here,
// once, so Forward+, deferred and multipass forward share one option with one meaning; the
// registry refuses two different declarations of a name.
//   pixel  (default) one fragment invocation per pixel and primitive, inputs at the pixel
//          centre, coverage and depth per sample, then the resolve (deferred: the G-buffer
//          once per pixel, edge pixels lit per sample: Lauritzen 2010).
//   sample every sample shaded on its own (supersampling): the reference's rate.
#include "core/renderer/error_model.h"
#include "core/renderer/knobs.h"

namespace tp {

enum class MsaaShading { Pixel, Sample };
const ChoiceKnob<MsaaShading>& msaaShadingKnob();

// The sample count and the shading rate, typed: what a pass picks its variant from.
struct Sampling {
    uint32_t samples = 1;
    MsaaShading shading = MsaaShading::Pixel;
    bool msaa() const { return samples > 1; }
    // Every sample shaded: MSAA on and `--msaa-shading sample`. At 1x there is one sample,
    // and the pipelines keep their 1x shaders (the knob changes nothing).
    bool perSample() const { return msaa() && shading == MsaaShading::Sample; }
    // MSAA on and shaded once per pixel (`--msaa-shading pixel`).
    bool perPixelUnderMsaa() const { return msaa() && shading == MsaaShading::Pixel; }
};
// For a renderer that declares msaaShadingKnob().
Sampling readSampling(const RenderSettings& s);
bool shadesPerPixelUnderMsaa(const RenderSettings& s);

// The bound of shading a pixel once at its centre instead of at each 4x sample, where the
// shading depends on the sample only through the view direction (directional lights,
// roughness-1 dielectrics, flat surfaces): the largest relative change of brdfCos over a move
// from the centre to the farthest standard 4x sample.
double centreShadingBound(const RenderSettings& s, const Scene& scene);
// For a pipeline's error model (stress): under MSAA at --msaa-shading pixel, that term, or
// "unbounded" where the case has local lights. Nothing at 1x or at the sample rate.
void addPixelRateErrorTerm(ErrorBound& b, const ErrorModelInput& in);

} // namespace tp
