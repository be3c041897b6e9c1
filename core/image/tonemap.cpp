// CPU tonemap: every pixel goes through tp::gpu::tonemap, the operator the viewer shader
// runs, so PNGs and the screen agree.
#include "core/image/tonemap.h"

#include <cmath>

#include "include/tonemap.h"

namespace tp {

ImageRGBA tonemapToDisplay(const ImageRGBA& linear, float exposureEv) {
    ImageRGBA out(linear.width, linear.height);
    for (size_t i = 0; i < linear.pixelCount(); ++i) {
        const float* in = &linear.rgba[i * 4];
        gpu::vec3 display = gpu::tonemap(gpu::vec3(in[0], in[1], in[2]), exposureEv);
        float* px = &out.rgba[i * 4];
        px[0] = display.x;
        px[1] = display.y;
        px[2] = display.z;
        px[3] = 1.0f;
    }
    return out;
}

float autoExposureEv(const ImageRGBA& linear) {
    // Rec.709 luminance; log-average (geometric mean) over pixels that can have a log.
    double logSum = 0.0;
    uint64_t count = 0;
    for (size_t i = 0; i < linear.pixelCount(); ++i) {
        const float* px = &linear.rgba[i * 4];
        if (!std::isfinite(px[0]) || !std::isfinite(px[1]) || !std::isfinite(px[2])) continue;
        double luminance = 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2];
        if (!(luminance > 0.0)) continue;
        logSum += std::log(luminance);
        ++count;
    }
    if (count == 0) return 0.0f;
    const double key = 0.18;
    double logAverage = logSum / double(count);
    return float(std::log2(key) - logAverage / std::log(2.0));
}

} // namespace tp
