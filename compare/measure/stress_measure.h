#pragma once
// Measuring one pipeline's image against the reference in a stress case and turning the
// figures into checks and a verdict (internal to triptych stress).
#include "compare/measure/stress_case.h"

namespace tp::cli {

constexpr float kHalfMax = 65504.0f; // largest finite fp16

// Fills the figures, the bound, the checks and the verdict of `p` (which ran).
void measureOutcome(StressOutcome& p, const StressOutcome& reference, const StressCaseResult& r,
                    const Scene& scene);

// Pixels whose RGB bits differ (images of one size; every pixel if the sizes differ).
uint64_t bitDifferentPixels(const ImageRGBA& a, const ImageRGBA& b);

// NaN and Inf pixels (RGB) of an image.
void countNonFinite(const ImageRGBA& image, uint64_t& nanPixels, uint64_t& infPixels);

} // namespace tp::cli
