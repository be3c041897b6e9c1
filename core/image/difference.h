#pragma once
// Difference images: a signed float image (test - reference, RGB, alpha 1) for EXR, and a
// heat map of max-channel |difference| on a fixed colour scale with a legend bar drawn
// into the PNG, so every map in one report can share one scale.
#include <array>
#include <vector>

#include "core/image/image.h"

namespace tp {

ImageRGBA signedDifference(const ImageRGBA& test, const ImageRGBA& reference);

// Heat map of |diff| in [0, scaleMax] (values above saturate; NaN/Inf drawn magenta),
// with a legend strip of `legendHeight` pixels under the image labelled 0 and scaleMax.
// Output is display-space RGBA ready for writePng; height = diff.height + legendHeight.
ImageRGBA heatMap(const ImageRGBA& signedDiff, float scaleMax, uint32_t legendHeight = 24);
// heatMap's ramp, low to high (RGB, linear display values): the viewer's GPU heat map reads it.
std::vector<std::array<float, 3>> heatRamp();

// A FLIP error map (values in [0, 1]) in the magma colour map FLIP's tool uses, with the same
// legend strip (0 to 1) under it; display-space RGBA for writePng.
ImageRGBA flipErrorMap(const ImageR32& flipValues, uint32_t legendHeight = 24);

// The scale of a signed difference's heat map, shared by the reports (compare, stress) and
// the viewer's difference view, so the same two images read the same in both: the 99th
// percentile of the per-pixel max-channel |value| (non-finite pixels ignored); 0 for an empty
// image.
float differencePercentile99(const ImageRGBA& signedDiff);

} // namespace tp
