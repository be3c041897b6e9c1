#pragma once
// Error metrics between a test image and a reference, kept in one table
// {name, description, function} so reports and tests loop over the same list.
// All metrics use the RGB channels only (alpha ignored); pixels where either image is
// NaN/Inf are excluded from every metric but nanInfCount.
#include <functional>
#include <string>
#include <vector>

#include "core/image/image.h"

namespace tp {

struct MetricsOptions {
    float relativeEpsilon = 1e-3f; // mean relative error: |t-r| / max(|r|, eps)
    float overThreshold = 0.01f;   // share of pixels whose max channel |t-r| exceeds this
    float psnrPeak = 1.0f;         // PSNR peak value (1 for tonemapped, chosen for HDR)
};

struct ErrorReport {
    double rmse = 0;   // sqrt(mean over pixels and RGB channels of (t-r)^2)
    double psnr = 0;   // 10 log10(peak^2 / mse); +inf when identical
    double maxAbs = 0; // max over pixels and RGB channels of |t-r|
    uint32_t maxAbsX = 0, maxAbsY = 0;
    double meanRelative = 0;       // mean over pixels and RGB channels of |t-r|/max(|r|,eps)
    double shareOverThreshold = 0; // fraction of compared pixels with max channel |t-r| > thr
    uint64_t nanInfCount = 0;      // pixels of the test image with a NaN or Inf in RGB
    uint64_t comparedPixels = 0;
    // Whether one pixel decides the RMSE: the largest share of the summed squared error that a
    // single pixel holds (0 when identical), and the RMSE over the other pixels. Near a light's
    // 1/d^2 pole one pixel can hold nearly all of it and rank pipelines by that pixel alone.
    double worstPixelShare = 0;
    double rmseWithoutWorstPixel = 0;
    uint32_t worstPixelX = 0, worstPixelY = 0; // that pixel (first in scan order on ties)
};

struct MetricInfo {
    std::string name;        // key in report.json
    std::string description; // one line for the report
    std::function<double(const ErrorReport&)> value;
};

// The table: rmse, psnr, max_abs, mean_relative, share_over_threshold, nan_inf,
// worst_pixel_share, rmse_without_worst_pixel.
const std::vector<MetricInfo>& metricTable();

// worstPixelShare above which the report says that one pixel decides the RMSE (half of it).
constexpr double kOnePixelDominates = 0.5;

// Pixels with a NaN or Inf in RGB (the nanInfCount of computeError, for a single image).
uint64_t countNonFinitePixels(const ImageRGBA& image);

// The brightest finite RGB value of an image, 1 when there is none above 0: the PSNR peak of
// linear HDR comparisons (a fixed 1 would make HDR PSNR depend on the scene's units).
float brightestFiniteChannel(const ImageRGBA& image);

// Images must have the same size; returns a report with comparedPixels=0 otherwise.
ErrorReport computeError(const ImageRGBA& test, const ImageRGBA& reference,
                         const MetricsOptions& options = {});

} // namespace tp
