#include "core/renderer/msaa_knob.h"

#include <algorithm>
#include <cmath>

#include "core/scene/scene.h"
#include "include/light_model.h"

namespace tp {

const ChoiceKnob<MsaaShading>& msaaShadingKnob() {
    static const ChoiceKnob<MsaaShading> k =
        ChoiceKnob<MsaaShading>{
            "msaa-shading",
            {{MsaaShading::Pixel, "pixel"}, {MsaaShading::Sample, "sample"}},
            "Shading rate under MSAA: pixel (one fragment invocation per pixel at its centre, "
            "coverage and depth per sample; deferred lights only edge pixels per sample, "
            "Lauritzen 2010) or sample (every sample shaded: supersampling, the reference's "
            "rate)"}
            .onlyUnderMsaa();
    return k;
}

Sampling readSampling(const RenderSettings& s) {
    return {s.msaa, msaaShadingKnob().in(s)};
}

bool shadesPerPixelUnderMsaa(const RenderSettings& s) {
    return readSampling(s).perPixelUnderMsaa();
}

// A pixel shaded once at its centre (deferred's non-edge pixels, Forward+ and multipass at
// --msaa-shading pixel), against the reference's per-sample shading. With
// directional lights and roughness-1 dielectrics on flat surfaces the shading depends on
// the sample only through the view direction, which moves by at most the distance from
// the centre to the farthest standard 4x sample (0.375 * sqrt(2) px) times the angle of a
// pixel. Bound: the largest relative change of brdfCos (the GPU's own code) over such a
// move, searched over light and view directions.
double centreShadingBound(const RenderSettings& s, const Scene& scene) {
    const double delta = 0.375 * std::sqrt(2.0) * scene.camera.yfov / double(s.height);
    gpu::SurfaceSample ss{};
    ss.normal = gpu::vec3(0, 0, 1);
    ss.metallic = 0.0f;
    ss.roughness = 1.0f;
    double worst = 0;
    for (const Material& m : scene.materials) {
        ss.baseColor = gpu::vec3(m.baseColorFactor);
        for (double lt = 0.05; lt < 1.55; lt += 0.1)
            for (double vt = 0.0; vt < 1.55; vt += 0.05)
                for (double phi = 0.0; phi < 3.15; phi += 0.2) {
                    gpu::vec3 l(float(std::sin(lt)), 0.0f, float(std::cos(lt)));
                    auto view = [&](double t, double p) {
                        return gpu::vec3(float(std::sin(t) * std::cos(p)),
                                         float(std::sin(t) * std::sin(p)), float(std::cos(t)));
                    };
                    ss.toViewer = view(vt, phi);
                    gpu::vec3 f0 = gpu::brdfCos(ss, l);
                    const double dphi = delta / std::max(std::sin(vt), 1e-3);
                    for (auto [dt, dp] :
                         {std::pair{-delta, 0.0}, {delta, 0.0}, {0.0, -dphi}, {0.0, dphi}}) {
                        ss.toViewer = view(std::max(0.0, vt + dt), phi + dp);
                        gpu::vec3 f1 = gpu::brdfCos(ss, l);
                        for (int c = 0; c < 3; ++c)
                            if (f0[c] > 0)
                                worst = std::max(worst, std::abs(double(f1[c]) - f0[c]) / f0[c]);
                    }
                }
    }
    return worst;
}

void addPixelRateErrorTerm(ErrorBound& b, const ErrorModelInput& in) {
    if (!shadesPerPixelUnderMsaa(in.settings)) return;
    if (!in.stressCase.directionalRoughOnly) {
        b.bounded = false;
        b.why = "--msaa-shading pixel shades each pixel once at its centre while the reference "
                "averages "
                "per-sample shadings: no per-pixel bound with local lights (docs/shading.md); the "
                "centre "
                "reference (--reference-msaa center) is its bound";
        return;
    }
    b.terms.push_back(
        {"centre shading (--msaa-shading pixel)", centreShadingBound(in.settings, in.scene), 0,
         "largest relative change of the BRDF when the view moves from the pixel centre to a "
         "4x sample (directional light, roughness 1)"});
}

} // namespace tp
