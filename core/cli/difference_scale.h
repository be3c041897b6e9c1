#pragma once
// The scale of a signed difference's heat map, shared by the reports (compare, stress) and
// the viewer's difference view, so the same two images read the same in both.
#include "core/image/image.h"

namespace tp {

// 99th percentile of the per-pixel max-channel |value| of a signed difference image
// (non-finite pixels ignored); 0 for an empty image.
float differencePercentile99(const ImageRGBA& signedDiff);

} // namespace tp
