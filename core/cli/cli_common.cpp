#include "core/cli/cli_common.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/image/tonemap.h"

namespace tp::cli {

void checkFrameCounts(int frames, int warmup) {
    if (frames < 1 || frames > 10000) throw UsageError("--frames must be between 1 and 10000");
    if (warmup < 0 || warmup > 1000) throw UsageError("--warmup must be between 0 and 1000");
}

float parseExposure(const std::string& text, const ImageRGBA& image) {
    if (text == "auto") return autoExposureEv(image);
    char* end = nullptr;
    float ev = std::strtof(text.c_str(), &end);
    if (end == text.c_str() || *end || !std::isfinite(ev) || std::abs(ev) > 64.0f)
        throw UsageError("--exposure '" + text + "': expected 'auto' or an EV between -64 and 64");
    return ev;
}

RunOptions progressRunOptions(const std::string& label, int warmup, int frames) {
    RunOptions r;
    r.warmupFrames = uint32_t(warmup);
    r.timedFrames = uint32_t(frames);
    const uint32_t timed = r.timedFrames, w = r.warmupFrames;
    // On a GPU the warm-up runs on past the frames asked for (frame_runner.cpp, kGpuWarmupMs):
    // those extra frames are warm-up too, and only the asked-for ones are printed.
    r.onFrame = [label, timed, w](uint32_t f, uint32_t total, double ms) {
        const bool warmup = f + timed < total;
        if (warmup && f >= w) return;
        std::fprintf(stderr, "  %s frame %u/%u: %.1f ms%s\n", label.c_str(), f + 1, total, ms,
                     warmup ? " (warm-up)" : "");
    };
    return r;
}

} // namespace tp::cli
