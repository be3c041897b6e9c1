// Error metrics (see metrics.h for the definitions). Sums are in double: a 4K image has
// ~25M channel terms and float accumulation would lose the small errors we look for.
#include "core/image/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tp {
namespace {

bool finiteRgb(const float* px) {
    return std::isfinite(px[0]) && std::isfinite(px[1]) && std::isfinite(px[2]);
}

struct Sums {
    double squared = 0;
    double relative = 0;
    uint64_t overThreshold = 0;
    double worstPixelSquared = 0; // the largest sum of squared RGB differences of one pixel
};

void accumulatePixel(const float* t, const float* r, uint32_t x, uint32_t y,
                     const MetricsOptions& options, Sums& sums, ErrorReport& report) {
    double pixelMax = 0, pixelSquared = 0;
    for (int c = 0; c < 3; ++c) {
        double diff = double(t[c]) - double(r[c]);
        double absDiff = std::abs(diff);
        pixelSquared += diff * diff;
        sums.relative +=
            absDiff / std::max(std::abs(double(r[c])), double(options.relativeEpsilon));
        pixelMax = std::max(pixelMax, absDiff);
    }
    sums.squared += pixelSquared;
    if (pixelSquared > sums.worstPixelSquared) {
        sums.worstPixelSquared = pixelSquared;
        report.worstPixelX = x;
        report.worstPixelY = y;
    }
    // Strictly greater: the first pixel in scan order wins ties, so the location is stable.
    if (pixelMax > report.maxAbs) {
        report.maxAbs = pixelMax;
        report.maxAbsX = x;
        report.maxAbsY = y;
    }
    if (pixelMax > double(options.overThreshold)) ++sums.overThreshold;
}

void finish(const Sums& sums, const MetricsOptions& options, ErrorReport& report) {
    // No pixel compared (all non-finite): leave the zero defaults rather than divide by 0.
    if (report.comparedPixels == 0) return;
    const double channels = double(report.comparedPixels) * 3.0;
    const double mse = sums.squared / channels;
    report.rmse = std::sqrt(mse);
    const double peak = double(options.psnrPeak);
    report.psnr =
        mse > 0.0 ? 10.0 * std::log10(peak * peak / mse) : std::numeric_limits<double>::infinity();
    report.meanRelative = sums.relative / channels;
    report.shareOverThreshold = double(sums.overThreshold) / double(report.comparedPixels);
    report.worstPixelShare = sums.squared > 0.0 ? sums.worstPixelSquared / sums.squared : 0.0;
    report.rmseWithoutWorstPixel =
        report.comparedPixels > 1
            ? std::sqrt(std::max(sums.squared - sums.worstPixelSquared, 0.0) / (channels - 3.0))
            : 0.0;
}

} // namespace

uint64_t countNonFinitePixels(const ImageRGBA& image) {
    uint64_t n = 0;
    for (size_t i = 0; i < image.pixelCount(); ++i)
        n += !finiteRgb(&image.rgba[i * 4]);
    return n;
}

float brightestFiniteChannel(const ImageRGBA& image) {
    float peak = 0.0f;
    for (size_t i = 0; i < image.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
            if (std::isfinite(image.rgba[i * 4 + c])) peak = std::max(peak, image.rgba[i * 4 + c]);
    return peak > 0.0f ? peak : 1.0f;
}

ErrorReport computeError(const ImageRGBA& test, const ImageRGBA& reference,
                         const MetricsOptions& options) {
    ErrorReport report;
    if (test.width != reference.width || test.height != reference.height ||
        test.rgba.size() != test.pixelCount() * 4 ||
        reference.rgba.size() != reference.pixelCount() * 4)
        return report;

    Sums sums;
    for (uint32_t y = 0; y < test.height; ++y) {
        for (uint32_t x = 0; x < test.width; ++x) {
            const float* t = test.at(x, y);
            const float* r = reference.at(x, y);
            bool testFinite = finiteRgb(t);
            if (!testFinite) ++report.nanInfCount;
            if (!testFinite || !finiteRgb(r)) continue;
            ++report.comparedPixels;
            accumulatePixel(t, r, x, y, options, sums, report);
        }
    }
    finish(sums, options, report);
    return report;
}

const std::vector<MetricInfo>& metricTable() {
    static const std::vector<MetricInfo> table = {
        {"rmse", "root mean square error over pixels and RGB channels",
         [](const ErrorReport& r) { return r.rmse; }},
        {"psnr", "peak signal-to-noise ratio in dB (inf when identical)",
         [](const ErrorReport& r) { return r.psnr; }},
        {"max_abs", "largest absolute difference of any RGB channel",
         [](const ErrorReport& r) { return r.maxAbs; }},
        {"mean_relative", "mean of |test-ref| / max(|ref|, epsilon) over pixels and RGB",
         [](const ErrorReport& r) { return r.meanRelative; }},
        {"share_over_threshold", "fraction of pixels whose max channel error exceeds threshold",
         [](const ErrorReport& r) { return r.shareOverThreshold; }},
        {"nan_inf", "pixels of the test image with a NaN or Inf in RGB",
         [](const ErrorReport& r) { return double(r.nanInfCount); }},
        {"worst_pixel_share", "share of the summed squared error held by the worst single pixel",
         [](const ErrorReport& r) { return r.worstPixelShare; }},
        {"rmse_without_worst_pixel", "root mean square error over every pixel but that one",
         [](const ErrorReport& r) { return r.rmseWithoutWorstPixel; }},
    };
    return table;
}

} // namespace tp
