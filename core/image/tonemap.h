#pragma once
// The CPU side of the one tonemap (shaders/include/tonemap.h holds the operator, shared with
// the GPU): exposure, then the operator, then the sRGB transfer function.
#include "core/image/image.h"

namespace tp {

// exposureEv: scene values are multiplied by 2^exposureEv before the operator.
ImageRGBA tonemapToDisplay(const ImageRGBA& linear, float exposureEv);

// Exposure (EV) that maps the log-average luminance of finite, non-zero pixels to 0.18
// (Reinhard's key value). Deterministic; 0 for an all-black image.
float autoExposureEv(const ImageRGBA& linear);

} // namespace tp
