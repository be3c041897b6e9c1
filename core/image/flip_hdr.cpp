// HDR-FLIP (Andersson et al. 2021): tonemap reference and test at exposures from `start` to
// `stop` and keep, per pixel, the largest LDR-FLIP. The range comes from the reference: at the
// start exposure its brightest luminance maps to 0.85 after the tone mapper (nothing visible
// is clipped), at the stop exposure its median luminance does (the darker half is seen well).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/image/flip.h"
#include "core/image/flip_filter.h"
#include "core/image/flip_ldr.h"

namespace tp {
namespace {

// Narkowicz's ACES fit as a ratio of quadratics in the exposed value, with his 0.6 pre-scale
// folded in: (k0 x^2 + k1 x + k2) / (k3 x^2 + k4 x + k5).
constexpr float kAces[6] = {0.6f * 0.6f * 2.51f, 0.6f * 0.03f, 0.0f,
                            0.6f * 0.6f * 2.43f, 0.6f * 0.59f, 0.14f};
constexpr float kExposureTarget = 0.85f;

// The input x >= 0 the tone mapper maps to `target`: the positive root of
// (k0 - t k3) x^2 + (k1 - t k4) x + (k2 - t k5) = 0.
float tonemapInverse(float target) {
    const float a = kAces[0] - target * kAces[3];
    const float b = kAces[1] - target * kAces[4];
    const float c = kAces[2] - target * kAces[5];
    return std::max(0.0f, (-b + std::sqrt(b * b - 4.0f * a * c)) / (2.0f * a));
}

float finiteOrZero(float v) {
    return std::isfinite(v) ? v : 0.0f;
}

// Rec. 709 luminance with its published 4-digit weights (not the Y row of flip_color.h's
// matrix): the reference tool's start/stop exposures match these to 1e-6 (tests/cpu/flip_test).
float luminance(const float* px) {
    return 0.2126f * finiteOrZero(px[0]) + 0.7152f * finiteOrZero(px[1]) +
           0.0722f * finiteOrZero(px[2]);
}

void tonemap(const ImageRGBA& linear, float exposure, flip::LinearPlanes& p) {
    const float scale = std::exp2(exposure);
    std::vector<float>* planes[3] = {&p.r, &p.g, &p.b};
    flip::parallelRows(int(linear.height), [&](int y0, int y1) {
        for (size_t i = size_t(y0) * linear.width; i < size_t(y1) * linear.width; ++i)
            for (int c = 0; c < 3; ++c)
                (*planes[c])[i] =
                    flipTonemapAces(finiteOrZero(linear.rgba[i * 4 + size_t(c)]) * scale);
    });
}

} // namespace

float flipTonemapAces(float x) {
    const float x2 = x * x;
    const float v =
        (kAces[0] * x2 + kAces[1] * x + kAces[2]) / (kAces[3] * x2 + kAces[4] * x + kAces[5]);
    return std::clamp(v, 0.0f, 1.0f);
}

FlipExposures flipAutoExposures(const ImageRGBA& referenceLinear) {
    FlipExposures e;
    const size_t n = referenceLinear.pixelCount();
    if (n == 0) return e;
    std::vector<float> lum(n);
    for (size_t i = 0; i < n; ++i)
        lum[i] = luminance(&referenceLinear.rgba[i * 4]);
    const float maxLum = *std::max_element(lum.begin(), lum.end());
    auto median = lum.begin() + std::ptrdiff_t(n / 2);
    std::nth_element(lum.begin(), median, lum.end());
    const float medianLum = *median;
    const float x = tonemapInverse(kExposureTarget);
    // A black reference (or a black median) has no range to speak of: fall back to [0, 0].
    e.start = maxLum > 0.0f ? std::log2(x / maxLum) : 0.0f;
    e.stop = medianLum > 0.0f ? std::log2(x / medianLum) : e.start;
    e.stop = std::max(e.stop, e.start);
    e.count = std::max(2, int(std::ceil(e.stop - e.start)));
    return e;
}

FlipResult hdrFlip(const ImageRGBA& testLinear, const ImageRGBA& referenceLinear, float ppd,
                   const FlipExposures* exposures) {
    FlipResult result;
    if (testLinear.width != referenceLinear.width || testLinear.height != referenceLinear.height ||
        testLinear.pixelCount() == 0)
        return result;
    result.exposures = exposures ? *exposures : flipAutoExposures(referenceLinear);
    const FlipExposures& e = result.exposures;
    const int count = std::max(e.count, 1);
    const float step = count > 1 ? (e.stop - e.start) / float(count - 1) : 0.0f;
    result.map = {testLinear.width, testLinear.height,
                  std::vector<float>(testLinear.pixelCount(), 0.0f)};
    const int w = int(testLinear.width), h = int(testLinear.height);
    flip::LinearPlanes ref(w, h), test(w, h);
    flip::FlipWorkspace workspace;
    for (int i = 0; i < count; ++i) {
        const float exposure = e.start + float(i) * step;
        tonemap(referenceLinear, exposure, ref);
        tonemap(testLinear, exposure, test);
        flip::flipLinear(ref, test, ppd, result.map.r.data(), workspace);
    }
    result.stats = poolFlip(result.map);
    return result;
}

} // namespace tp
