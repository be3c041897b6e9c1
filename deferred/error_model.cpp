#include "deferred/error_model.h"

#include <algorithm>
#include <cmath>

#include "include/light_model.h"
#include "include/tonemap.h"

namespace tp {
namespace {

// Smallest non-zero base colour channel among the materials: 8-bit sRGB moves it most.
float darkestBase(const Scene& scene) {
    float d = 1.0f;
    for (const Material& m : scene.materials)
        for (int c = 0; c < 3; ++c)
            if (m.baseColorFactor[c] > 0.0f) d = std::min(d, m.baseColorFactor[c]);
    return d;
}

// Smallest roughness that 8 bits cannot hold exactly (values at or below the clamp 0.03 on
// both sides of the rounding, and multiples of 1/255, come back unchanged); 0 when none.
float inexactRoughness(const Scene& scene) {
    float r = 0.0f;
    for (const Material& m : scene.materials) {
        float q = std::round(m.roughnessFactor * 255.0f) / 255.0f;
        if (q == m.roughnessFactor) continue;
        if (std::max(q, m.roughnessFactor) <= TP_MIN_ROUGHNESS) continue;
        float eff = std::max(m.roughnessFactor, TP_MIN_ROUGHNESS);
        if (r == 0.0f || eff < r) r = eff;
    }
    return r;
}

// Deferred shades a non-edge pixel once at its centre, the reference each sample. With
// directional lights and roughness-1 dielectrics on flat surfaces the shading depends on
// the sample only through the view direction, which moves by at most the distance from
// the centre to the farthest standard 4x sample (0.375 * sqrt(2) px) times the angle of a
// pixel. Bound: the largest relative change of brdfCos (the GPU's own code) over such a
// move, searched over light and view directions.
double centreShadingTerm(const RenderSettings& s, const Scene& scene) {
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
                        return gpu::vec3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
                    };
                    ss.toViewer = view(vt, phi);
                    gpu::vec3 f0 = gpu::brdfCos(ss, l);
                    const double dphi = delta / std::max(std::sin(vt), 1e-3);
                    for (auto [dt, dp] : {std::pair{-delta, 0.0}, {delta, 0.0}, {0.0, -dphi}, {0.0, dphi}}) {
                        ss.toViewer = view(std::max(0.0, vt + dt), phi + dp);
                        gpu::vec3 f1 = gpu::brdfCos(ss, l);
                        for (int c = 0; c < 3; ++c)
                            if (f0[c] > 0) worst = std::max(worst, std::abs(double(f1[c]) - f0[c]) / f0[c]);
                    }
                }
    }
    return worst;
}

void addCompactGBuffer(ErrorBound& b, const ErrorModelInput& in) {
    const float d = darkestBase(in.scene);
    const double srgb = gpu::srgbEncode(d);
    b.terms.push_back({"8-bit sRGB base colour", 2.4 * (0.5 / 255.0) / (srgb + 0.055), 0,
                       "2.4 * (0.5/255) / (s + 0.055) at the darkest base channel " + std::to_string(d)});
    const float r = inexactRoughness(in.scene);
    if (r > 0.0f)
        b.terms.push_back({"8-bit roughness", 6.0 * (0.5 / 255.0) / r, 0,
                           "6 * (0.5/255) / r at r = " + std::to_string(r) + " (|dlnD/dlnr| <= 4, |dlnVis/dlnr| <= 2)"});
    if (in.stressCase.freeNormals)
        b.terms.push_back({"octahedral normals", 6.5e-5 * 10.0, 0,
                           "RG16_SNORM octahedral normals move <= 6.5e-5 rad; times |tan| <= 10 of the light "
                           "angle where n.l >= 0.1"});
}

} // namespace

void deferredErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    b.terms.push_back({"position from depth", 2.5e-4, 2.5e-8,
                       "positions reconstructed from D32 depth with the inverse view-projection, fp32 sums in "
                       "tile order: docs/deferred.md's per-pixel bound (2.5e-4 of |r| + 1e-4)"});
    if (in.settings.text("gbuffer") == "compact") addCompactGBuffer(b, in);
    // At 1x, and with the sample-rate G-buffer (every sample's material evaluated and lit at
    // that sample, as the supersampled reference does), nothing is shaded at the centre.
    if (in.settings.msaa == 1 || in.settings.text("gbuffer-msaa") == "sample") return;
    if (!in.stressCase.directionalRoughOnly) {
        b.bounded = false;
        b.why = "non-edge pixels are shaded once at the centre while the reference averages per-sample "
                "shadings: no per-pixel bound with local lights (docs/deferred.md)";
        return;
    }
    b.terms.push_back({"centre shading of non-edge pixels", centreShadingTerm(in.settings, in.scene), 0,
                       "largest relative change of the BRDF when the view moves from the pixel centre to a "
                       "4x sample (directional light, roughness 1)"});
}

} // namespace tp
