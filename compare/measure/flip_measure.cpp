// FLIP for compare and sweep (see flip_measure.h).
#include "compare/measure/flip_measure.h"

#include <cmath>
#include <CLI/CLI.hpp>

#include "core/image/image_io.h"
#include "core/image/tonemap.h"

namespace tp::cli {
namespace {

nlohmann::json pooledJson(const FlipStats& s) {
    return {{"mean", s.mean},
            {"weighted_median", s.weightedMedian},
            {"weighted_q1", s.weightedQ1},
            {"weighted_q3", s.weightedQ3},
            {"min", s.min},
            {"max", s.max}};
}

} // namespace

FlipReference prepareFlipReference(const ImageRGBA& referenceLinear, float exposureEv,
                                   float distanceMetres) {
    FlipReference r;
    r.linear = &referenceLinear;
    r.display = asStoredInPng(tonemapToDisplay(referenceLinear, exposureEv));
    r.exposures = flipAutoExposures(referenceLinear);
    r.exposureEv = exposureEv;
    r.ppd = flipPixelsPerDegree(distanceMetres);
    return r;
}

FlipMeasure measureFlip(const ImageRGBA& testLinear, const FlipReference& reference,
                        bool keepMaps) {
    FlipMeasure m;
    FlipResult ldr = ldrFlip(asStoredInPng(tonemapToDisplay(testLinear, reference.exposureEv)),
                             reference.display, reference.ppd);
    FlipResult hdr = hdrFlip(testLinear, *reference.linear, reference.ppd, &reference.exposures);
    if (ldr.map.r.empty() || hdr.map.r.empty()) return m;
    m.measured = true;
    m.ldr = ldr.stats;
    m.hdr = hdr.stats;
    m.exposures = hdr.exposures;
    if (keepMaps) {
        m.ldrMap = std::move(ldr.map);
        m.hdrMap = std::move(hdr.map);
    }
    return m;
}

FlipMeasure measureFlip(const ImageRGBA& testLinear, const ImageRGBA& referenceLinear,
                        float exposureEv, float distanceMetres, bool keepMaps) {
    return measureFlip(testLinear,
                       prepareFlipReference(referenceLinear, exposureEv, distanceMetres), keepMaps);
}

nlohmann::json flipJson(const FlipMeasure& m) {
    if (!m.measured) return nullptr;
    nlohmann::json hdr = pooledJson(m.hdr);
    hdr["start_exposure"] = m.exposures.start;
    hdr["stop_exposure"] = m.exposures.stop;
    hdr["exposures"] = m.exposures.count;
    return {{"ldr", pooledJson(m.ldr)}, {"hdr", hdr}};
}

nlohmann::json flipConditionsJson(float distanceMetres) {
    // Rounded to 6 decimals: the float option read back as double would print 0.699999988.
    return {
        {"viewing_distance_m", std::round(double(distanceMetres) * 1e6) / 1e6},
        {"pixels_per_degree", flipPixelsPerDegree(distanceMetres)},
        {"monitor", "0.7 m wide, 3840 pixels across (FLIP's default)"},
        {"ldr_input", "the tonemapped PNGs (8-bit sRGB, the report's exposure)"},
        {"hdr_input", "the linear EXR values; exposures from the reference (ACES tone mapper)"},
        {"pooling", "mean over pixels; weighted percentiles weight each pixel by its own error"}};
}

void addFlipDistanceOption(CLI::App& cmd, float& distanceMetres) {
    cmd.add_option("--flip-distance", distanceMetres,
                   "Viewing distance in metres for FLIP and HDR-FLIP, from a 0.7 m wide 4K monitor "
                   "(0.7: FLIP's default, 67 pixels per degree); 0.1 to 10")
        ->capture_default_str();
}

void checkFlipDistance(float distanceMetres) {
    if (!(distanceMetres >= 0.1f && distanceMetres <= 10.0f))
        throw UsageError("--flip-distance must be between 0.1 and 10 metres");
}

} // namespace tp::cli
