#pragma once
// What the compare-side commands (compare, render, sweep, stress, info) share beyond the
// options every command has (core/cli): frame counts, exposure, progress lines.
#include <string>

#include "core/cli/options.h"
#include "core/cli/scene_input.h"
#include "core/image/image.h"
#include "core/runner/frame_runner.h"

namespace tp::cli {

// --frames / --warmup bounds shared by the commands that time frames.
void checkFrameCounts(int frames, int warmup);

// Exposure in EV: "auto" (log-average luminance of `image` to 0.18) or a number in [-64, 64].
float parseExposure(const std::string& text, const ImageRGBA& image);
// Warm-up then timed frames, one progress line per frame on stderr prefixed by `label`.
RunOptions progressRunOptions(const std::string& label, int warmup, int frames);

} // namespace tp::cli
