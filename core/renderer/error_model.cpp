#include "core/renderer/error_model.h"

#include <algorithm>
#include <cmath>

#include "core/renderer/position_allowance.h"
#include "include/tonemap.h"

namespace tp {
namespace {

constexpr double kCodeTerm = 1e-5; // same code in different shaders: a few ulps per term

double tonemapAt(double x) {
    return gpu::tonemap(gpu::vec3(float(x)), 0.0f).x;
}

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
            "fp32 sums of <= " + std::to_string(lights) +
                " non-negative light terms (+8 for ambient, emissive, "
                "resolve) against the reference's fp64 sum: (n + 8) * 2^-24"};
}

// A hard-edged spot (position_allowance.h: isHardSpot) is a step in the image: a pixel whose
// points may straddle its cone edge can be lit by it in one image and not in the other,
// whatever the pipeline. Those pixels get the spot's whole reflected light on top of the
// model's own allowance; every other pixel keeps the model's bound.
void addHardSpotEdges(ErrorBound& b, const ErrorModelInput& in) {
    const ImageR32 edges = hardSpotEdgeAllowance(in.scene, *in.referenceDepth, in.settings.msaa);
    if (edges.r.empty()) return;
    PixelAllowance& p = b.perPixel;
    if (p.radiance.r.size() == edges.r.size()) {
        for (size_t i = 0; i < edges.r.size(); ++i)
            p.radiance.r[i] += edges.r[i];
        p.name += " + hard spot edges";
        p.why += "; plus, where a pixel's points may straddle a hard spot's cone edge, the spot's "
                 "whole reflected light";
    } else {
        p = {"hard spot edges",
             "a spot with inner = outer is a step: where a pixel's points may straddle its cone "
             "edge (a ball of one pixel width at the point's depth meets the cone's 1e-4 ramp), "
             "the spot's whole reflected light (docs/stress.md)",
             edges};
    }
}

} // namespace

double ErrorBound::relative() const {
    double r = 0;
    for (const BoundTerm& t : terms)
        r += t.relative;
    return r;
}

double ErrorBound::absolute() const {
    double a = 0;
    for (const BoundTerm& t : terms)
        a += t.absolute;
    return a;
}

double ErrorBound::tonemapped(float ev) const {
    return tonemapRelativeSlope() * relative() +
           tonemapAbsoluteSlope() * std::exp2(double(ev)) * absolute();
}

void addFp16StorageTerm(ErrorBound& b, int roundings, const std::string& stores) {
    b.terms.push_back(
        {"fp16 colour storage", roundings * kHalfUlp16, roundings * 6e-8,
         std::to_string(roundings) + " fp16 store(s) (" + stores +
             "): each below one ulp, 2^-10 "
             "relative (Vulkan allows rounding toward zero), 6e-8 absolute in the subnormals"});
}

void addBlendedLayersTerm(ErrorBound& b, const ErrorModelInput& in, uint32_t blendsPerLayer,
                          bool fp16Store, const std::string& how) {
    const uint32_t layers = in.stressCase.blendedLayers;
    if (layers == 0) return;
    const double blends = double(layers) * double(blendsPerLayer);
    const std::string count = std::to_string(int64_t(blends)) + " blends per pixel at most (" +
                              std::to_string(layers) + " layers, " + how + ")";
    b.terms.push_back({"blended layers: fp32 blend arithmetic", 4.0 * (blends + layers) * kUlp32, 0,
                       count + " and " + std::to_string(layers) +
                           " in the reference, each <= 4 fp32 roundings of values weighing <= "
                           "the pixel: 4 * (B + L) * 2^-24"});
    if (fp16Store)
        b.terms.push_back(
            {"blended layers: fp16 stores", blends * kHalfUlp16, blends * 6e-8,
             count + ", each result stored in the RGBA16F target once: B * 2^-10, B * 6e-8"});
}

double tonemapRelativeSlope() {
    static const double k = tonemapSlope(true);
    return k;
}

double tonemapAbsoluteSlope() {
    static const double s0 = tonemapSlope(false);
    return s0;
}

ErrorBound expectedBound(const ErrorModel& model, const ErrorModelInput& in) {
    ErrorBound b;
    b.terms.push_back(summation(in.scene.lights.size()));
    b.terms.push_back({"same code, other shader", kCodeTerm, 1e-7,
                       "the one light model compiled into different shaders: a few ulps per term"});
    if (model)
        model(b, in);
    else
        b.terms.push_back({"no precision model", 2 * kHalfUlp16, 1.2e-7,
                           "a pipeline stress does not know: two fp16 roundings assumed"});
    if (in.referenceDepth) addHardSpotEdges(b, in);
    if (b.bounded) b.why = "sum of the terms; tonemapped: K * relative + S0 * 2^ev * absolute";
    return b;
}

} // namespace tp
