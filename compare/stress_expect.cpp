// Per-pipeline precision models for `triptych stress`. Each term is the worst case of one
// documented step of the pipeline's method; docs/stress.md repeats them with the reasoning.
#include "compare/stress_expect.h"

#include <algorithm>
#include <cmath>

#include "include/light_model.h"
#include "include/tonemap.h"

namespace tp::cli {
namespace {

constexpr double kHalfUlp16 = 1.0 / 1024.0; // fp16 store: below one ulp, 2^-10 relative
constexpr double kUlp32 = 1.0 / 16777216.0; // 2^-24
constexpr double kCodeTerm = 1e-5;          // same code in different shaders: a few ulps per term

double tonemapAt(double x) { return gpu::tonemap(gpu::vec3(float(x)), 0.0f).x; }

// sup over x of the slope of T (absolute) or of x * T'(x) (relative), on a log grid from
// 1e-8 to 1e8 with central differences of 1e-3 relative, times 1.01 for the grid's gaps.
double tonemapSlope(bool relative) {
    double best = 0;
    for (double e = -8.0; e <= 8.0; e += 0.001) {
        double x = std::pow(10.0, e), h = x * 1e-3;
        double slope = (tonemapAt(x + h) - tonemapAt(x - h)) / (2 * h);
        best = std::max(best, relative ? x * slope : slope);
    }
    return best * 1.01;
}

BoundTerm summation(size_t lights) {
    return {"summation", double(lights + 8) * kUlp32, 0,
            "fp32 sums of <= " + std::to_string(lights) + " non-negative light terms (+8 for ambient, emissive, "
            "resolve) against the reference's fp64 sum: (n + 8) * 2^-24"};
}

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

void addForwardPlus(ErrorBound& b, const RenderSettings& s) {
    const int roundings = s.msaa > 1 ? 2 : 1;
    b.terms.push_back({"fp16 colour storage", roundings * kHalfUlp16, roundings * 6e-8,
                       std::to_string(roundings) + " fp16 store(s) (sample, resolve): each below one ulp, 2^-10 "
                       "relative (Vulkan allows rounding toward zero), 6e-8 absolute in the subnormals"});
}

void addMultipass(ErrorBound& b, const RenderSettings& s, size_t lights) {
    if (s.accum == "fp16")
        b.terms.push_back({"fp16 accumulation", double(lights + 2) * kHalfUlp16, double(lights + 2) * 6e-8,
                           "one fp16 rounding per additive pass"});
    else
        b.terms.push_back({"fp32 accumulation", 0, 0, "each additive pass rounds in fp32: inside the summation term"});
}

void addDeferred(ErrorBound& b, const stress::StressCase& c, const Scene& scene, const RenderSettings& s) {
    b.terms.push_back({"position from depth", 2.5e-4, 2.5e-8,
                       "positions reconstructed from D32 depth with the inverse view-projection, fp32 sums in "
                       "tile order: docs/deferred.md's per-pixel bound (2.5e-4 of |r| + 1e-4)"});
    if (s.gbuffer == "compact") {
        const float d = darkestBase(scene);
        const double srgb = gpu::srgbEncode(d);
        b.terms.push_back({"8-bit sRGB base colour", 2.4 * (0.5 / 255.0) / (srgb + 0.055), 0,
                           "2.4 * (0.5/255) / (s + 0.055) at the darkest base channel " + std::to_string(d)});
        const float r = inexactRoughness(scene);
        if (r > 0.0f)
            b.terms.push_back({"8-bit roughness", 6.0 * (0.5 / 255.0) / r, 0,
                               "6 * (0.5/255) / r at r = " + std::to_string(r) +
                                   " (|dlnD/dlnr| <= 4, |dlnVis/dlnr| <= 2)"});
        if (c.freeNormals)
            b.terms.push_back({"octahedral normals", 6.5e-5 * 10.0, 0,
                               "RG16_SNORM octahedral normals move <= 6.5e-5 rad; times |tan| <= 10 of the light "
                               "angle where n.l >= 0.1"});
    }
    if (s.msaa > 1) {
        if (!c.directionalRoughOnly) {
            b.bounded = false;
            b.why = "non-edge pixels are shaded once at the centre while the reference averages per-sample "
                    "shadings: no per-pixel bound with local lights (docs/deferred.md)";
            return;
        }
        b.terms.push_back({"centre shading of non-edge pixels", centreShadingTerm(s, scene), 0,
                           "largest relative change of the BRDF when the view moves from the pixel centre to a "
                           "4x sample (directional light, roughness 1)"});
    }
}

} // namespace

double ErrorBound::relative() const {
    double r = 0;
    for (const BoundTerm& t : terms) r += t.relative;
    return r;
}

double ErrorBound::absolute() const {
    double a = 0;
    for (const BoundTerm& t : terms) a += t.absolute;
    return a;
}

double ErrorBound::tonemapped(float ev) const {
    return tonemapRelativeSlope() * relative() + tonemapAbsoluteSlope() * std::exp2(double(ev)) * absolute();
}

double tonemapRelativeSlope() {
    static const double k = tonemapSlope(true);
    return k;
}

double tonemapAbsoluteSlope() {
    static const double s0 = tonemapSlope(false);
    return s0;
}

ErrorBound expectedBound(const std::string& pipeline, const stress::StressCase& c, const Scene& scene,
                         const RenderSettings& s) {
    ErrorBound b;
    b.terms.push_back(summation(scene.lights.size()));
    b.terms.push_back({"same code, other shader", kCodeTerm, 1e-7,
                       "the one light model compiled into different shaders: a few ulps per term"});
    if (pipeline == "forwardplus") addForwardPlus(b, s);
    else if (pipeline == "multipass_forward") addMultipass(b, s, scene.lights.size());
    else if (pipeline == "deferred") addDeferred(b, c, scene, s);
    else {
        b.terms.push_back({"no precision model", 2 * kHalfUlp16, 1.2e-7,
                           "a pipeline stress does not know: two fp16 roundings assumed"});
    }
    if (b.bounded) b.why = "sum of the terms; tonemapped: K * relative + S0 * 2^ev * absolute";
    return b;
}

} // namespace tp::cli
