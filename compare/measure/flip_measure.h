#pragma once
// FLIP and HDR-FLIP of a pipeline's image against the reference, as compare and sweep report
// them: LDR-FLIP on the tonemapped images exactly as their PNGs hold them (8-bit sRGB, so
// NVIDIA's tool run on the two PNGs prints the same figures), HDR-FLIP on the linear images
// (exposure range from the reference). The viewing distance is --flip-distance.
#include <nlohmann/json.hpp>

#include "core/cli/cli_common.h"
#include "core/image/flip.h"

namespace tp::cli {

struct FlipMeasure {
    bool measured = false;
    FlipStats ldr, hdr;
    FlipExposures exposures; // HDR-FLIP's range, from the reference
    ImageR32 hdrMap, ldrMap; // kept only when asked for
};

// What FLIP needs of the reference, computed once for all the images measured against it:
// its display image as its PNG holds it, and HDR-FLIP's exposure range.
struct FlipReference {
    const ImageRGBA* linear = nullptr;
    ImageRGBA display;
    FlipExposures exposures;
    float exposureEv = 0, ppd = 0;
};
FlipReference prepareFlipReference(const ImageRGBA& referenceLinear, float exposureEv,
                                   float distanceMetres);

FlipMeasure measureFlip(const ImageRGBA& testLinear, const FlipReference& reference, bool keepMaps);
// One image against a reference measured once (tests).
FlipMeasure measureFlip(const ImageRGBA& testLinear, const ImageRGBA& referenceLinear,
                        float exposureEv, float distanceMetres, bool keepMaps);

// {"ldr": {mean, weighted_median, weighted_q1, weighted_q3, min, max},
//  "hdr": {the same, start_exposure, stop_exposure, exposures}}
nlohmann::json flipJson(const FlipMeasure& m);
// The run-wide conditions: distance, pixels per degree, monitor, inputs, what the fields mean.
nlohmann::json flipConditionsJson(float distanceMetres);

// --flip-distance METRES (default 0.7, FLIP's own): one option for compare and sweep.
void addFlipDistanceOption(CLI::App& cmd, float& distanceMetres);
// Refuses a distance outside [0.1, 10] m with a one-line UsageError (beyond 10 m the CSF
// filters grow past 1000 pixels and FLIP takes minutes).
void checkFlipDistance(float distanceMetres);

} // namespace tp::cli
