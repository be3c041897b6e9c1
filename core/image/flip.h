#pragma once
// FLIP and HDR-FLIP: NVIDIA's perceptual error metrics for rendered images, implemented from
// the papers (Andersson et al., "FLIP: A Difference Evaluator for Alternating Images",
// HPG 2020; "Visualizing Errors in Rendered High Dynamic Range Images", EG 2021) and
// cross-checked against the pooled values of NVIDIA's reference tool (tests/cpu/flip_test.cpp,
// /work/shared/flip/MANIFEST.txt).
//
// FLIP approximates what a viewer flipping between the two images at a given distance would
// notice: a per-pixel error in [0, 1] from a colour difference (after filtering both images
// with the eye's contrast sensitivity, in a perceptually uniform space) boosted where edges or
// points differ. HDR-FLIP tonemaps both linear images at a range of exposures derived from the
// reference and keeps the per-pixel maximum of LDR-FLIP over them.
//
// Pixels with a NaN or Inf in the inputs are evaluated as black (the nan_inf metric counts
// them); alpha is ignored.
#include "core/image/image.h"

namespace tp {

// FLIP's default viewing conditions: a 0.7 m wide 3840-pixel monitor seen from 0.7 m,
// 3840 * pi / 180 = 67.02 pixels per degree.
inline constexpr float kFlipDefaultDistanceMetres = 0.7f;
inline constexpr float kFlipMonitorWidthMetres = 0.7f;
inline constexpr float kFlipMonitorWidthPixels = 3840.0f;

// Pixels per degree of visual angle at `distanceMetres` from the default monitor (small-angle,
// as FLIP computes it: distance * pixels / width * pi / 180).
float flipPixelsPerDegree(float distanceMetres = kFlipDefaultDistanceMetres);

// Pooled values of a FLIP map, defined as FLIP's tool prints them: the mean over all pixels,
// min and max, and percentiles of the distribution in which each pixel is weighted by its own
// error (so the weighted median says "half of the total error sits in pixels at or below").
struct FlipStats {
    double mean = 0;
    double weightedMedian = 0;
    double weightedQ1 = 0;
    double weightedQ3 = 0;
    double min = 0;
    double max = 0;
};
FlipStats poolFlip(const ImageR32& map);

// HDR-FLIP's exposure range (stops relative to the linear values).
struct FlipExposures {
    float start =
        0; // shortest exposure: the reference's brightest luminance just below tonemap 0.85
    float stop = 0; // longest: its median luminance at 0.85
    int count = 0;  // max(2, ceil(stop - start)), evenly spaced from start to stop
};
FlipExposures flipAutoExposures(const ImageRGBA& referenceLinear);

// HDR-FLIP's tone mapper: Narkowicz's ACES fit (input pre-scaled by 0.6), clamped to [0,1].
float flipTonemapAces(float linear);

struct FlipResult {
    ImageR32 map; // per pixel, in [0, 1]; empty when the sizes differ
    FlipStats stats;
    FlipExposures exposures; // HDR-FLIP only: the range used
};

// LDR-FLIP of display images: RGB in [0,1] sRGB-encoded (what a PNG holds, decoded /255).
FlipResult ldrFlip(const ImageRGBA& testDisplay, const ImageRGBA& referenceDisplay, float ppd);

// HDR-FLIP of linear images; the exposure range from the reference unless given.
FlipResult hdrFlip(const ImageRGBA& testLinear, const ImageRGBA& referenceLinear, float ppd,
                   const FlipExposures* exposures = nullptr);

} // namespace tp
