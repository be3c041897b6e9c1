// Metrics, tonemap and difference images on tiny images whose expected values are worked
// out by hand in the comments (Falcor's metrics shipped wrong for lack of exactly this).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/image/difference.h"
#include "core/image/metrics.h"
#include "core/image/tonemap.h"
#include "include/tonemap.h"

using namespace tp;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

ImageRGBA uniform(uint32_t w, uint32_t h, float r, float g, float b, float a = 1.0f) {
    ImageRGBA image(w, h);
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        image.rgba[i * 4 + 0] = r;
        image.rgba[i * 4 + 1] = g;
        image.rgba[i * 4 + 2] = b;
        image.rgba[i * 4 + 3] = a;
    }
    return image;
}

void setRgb(ImageRGBA& image, uint32_t x, uint32_t y, float r, float g, float b) {
    float* px = image.at(x, y);
    px[0] = r;
    px[1] = g;
    px[2] = b;
}

// Reference: every channel 0.5. Test (differences chosen exactly representable in float):
//   (0,0) = reference                   diff (0, 0, 0)
//   (1,0) R = 0.625                     diff (+0.125, 0, 0)
//   (0,1) G = 0.25                      diff (0, -0.25, 0)
//   (1,1) B = 1.0                       diff (0, 0, +0.5)
struct HandPair {
    ImageRGBA test = uniform(2, 2, 0.5f, 0.5f, 0.5f);
    ImageRGBA reference = uniform(2, 2, 0.5f, 0.5f, 0.5f);
    HandPair() {
        setRgb(test, 1, 0, 0.625f, 0.5f, 0.5f);
        setRgb(test, 0, 1, 0.5f, 0.25f, 0.5f);
        setRgb(test, 1, 1, 0.5f, 0.5f, 1.0f);
    }
};

} // namespace

TEST(Metrics, HandComputedTwoByTwo) {
    HandPair pair;
    ErrorReport r = computeError(pair.test, pair.reference);
    EXPECT_EQ(r.comparedPixels, 4u);
    EXPECT_EQ(r.nanInfCount, 0u);
    // Squared errors: 0.125^2 + 0.25^2 + 0.5^2 = 0.015625 + 0.0625 + 0.25 = 0.328125 over
    // 4 pixels * 3 channels = 12 terms: MSE = 0.02734375, RMSE = 0.165359456941537.
    EXPECT_NEAR(r.rmse, 0.165359456941537, 1e-12);
    // PSNR (peak 1) = 10 log10(1 / 0.02734375) = 15.631419252975927 dB.
    EXPECT_NEAR(r.psnr, 15.631419252975927, 1e-9);
    // Largest |diff| is 0.5 (B of pixel (1,1)).
    EXPECT_DOUBLE_EQ(r.maxAbs, 0.5);
    EXPECT_EQ(r.maxAbsX, 1u);
    EXPECT_EQ(r.maxAbsY, 1u);
    // Relative: |d| / 0.5 = 0.25 + 0.5 + 1.0 = 1.75 over 12 terms = 0.145833...
    EXPECT_NEAR(r.meanRelative, 1.75 / 12.0, 1e-12);
    // Default threshold 0.01: the three changed pixels exceed it, the first does not.
    EXPECT_DOUBLE_EQ(r.shareOverThreshold, 0.75);
}

// The worst pixel's share: pixel (1,1) holds 0.25 of the summed 0.328125, i.e. 0.761904...;
// without it 0.015625 + 0.0625 = 0.078125 over the other 3 pixels * 3 channels = 9 terms:
// RMSE 0.0931694990624912.
TEST(Metrics, WorstPixelShareAndRmseWithoutIt) {
    HandPair pair;
    ErrorReport r = computeError(pair.test, pair.reference);
    EXPECT_NEAR(r.worstPixelShare, 0.25 / 0.328125, 1e-12);
    EXPECT_GT(r.worstPixelShare, kOnePixelDominates);
    EXPECT_NEAR(r.rmseWithoutWorstPixel, 0.0931694990624912, 1e-12);
    EXPECT_EQ(r.worstPixelX, 1u);
    EXPECT_EQ(r.worstPixelY, 1u);
    // Identical images: no error, no share.
    ErrorReport same = computeError(pair.reference, pair.reference);
    EXPECT_EQ(same.worstPixelShare, 0.0);
    EXPECT_EQ(same.rmseWithoutWorstPixel, 0.0);
}

TEST(Metrics, ThresholdUsesMaxChannelPerPixel) {
    HandPair pair;
    MetricsOptions options;
    options.overThreshold = 0.2f; // only 0.25 and 0.5 exceed: 2 of 4 pixels
    EXPECT_DOUBLE_EQ(computeError(pair.test, pair.reference, options).shareOverThreshold, 0.5);
    options.overThreshold = 0.5f; // strictly greater: 0.5 itself does not count
    EXPECT_DOUBLE_EQ(computeError(pair.test, pair.reference, options).shareOverThreshold, 0.0);
}

TEST(Metrics, PsnrPeakScalesPsnr) {
    HandPair pair;
    MetricsOptions options;
    options.psnrPeak = 4.0f; // +20 log10(4) = +12.041199826559248 dB over peak 1
    ErrorReport r = computeError(pair.test, pair.reference, options);
    EXPECT_NEAR(r.psnr, 15.631419252975927 + 12.041199826559248, 1e-9);
}

TEST(Metrics, RelativeErrorUsesEpsilonNearZero) {
    // Reference 0 everywhere, test R = 0.002, G = B = 0: relative R = 0.002 / max(0, 1e-3) = 2,
    // G = B = 0, so the mean over 3 channels is 2/3.
    ImageRGBA reference = uniform(1, 1, 0.0f, 0.0f, 0.0f);
    ImageRGBA test = uniform(1, 1, 0.002f, 0.0f, 0.0f);
    EXPECT_NEAR(computeError(test, reference).meanRelative, 2.0 / 3.0, 1e-6);
}

TEST(Metrics, IdenticalImagesHaveInfinitePsnr) {
    ImageRGBA image = uniform(3, 2, 0.1f, 2.0f, 30.0f);
    ErrorReport r = computeError(image, image);
    EXPECT_EQ(r.rmse, 0.0);
    EXPECT_TRUE(std::isinf(r.psnr) && r.psnr > 0);
    EXPECT_EQ(r.maxAbs, 0.0);
    EXPECT_EQ(r.meanRelative, 0.0);
    EXPECT_EQ(r.shareOverThreshold, 0.0);
    EXPECT_EQ(r.comparedPixels, 6u);
}

TEST(Metrics, AlphaIsIgnored) {
    ImageRGBA reference = uniform(2, 1, 0.3f, 0.3f, 0.3f, 1.0f);
    ImageRGBA test = uniform(2, 1, 0.3f, 0.3f, 0.3f, 0.0f);
    EXPECT_EQ(computeError(test, reference).maxAbs, 0.0);
}

TEST(Metrics, NanInfCountedAndExcluded) {
    // 2x2; reference 0 everywhere except a NaN at (1,1).
    // Test: (0,0) NaN in G, (1,0) +Inf in B, (0,1) R = 0.25, (1,1) finite 7.
    // nanInfCount counts the test's two bad pixels; (1,1) is excluded because the reference
    // is NaN there. Only (0,1) is compared: MSE = 0.25^2 / 3, max 0.25 at (0,1).
    ImageRGBA reference = uniform(2, 2, 0.0f, 0.0f, 0.0f);
    setRgb(reference, 1, 1, kNaN, 0.0f, 0.0f);
    ImageRGBA test = uniform(2, 2, 0.0f, 0.0f, 0.0f);
    setRgb(test, 0, 0, 0.0f, kNaN, 0.0f);
    setRgb(test, 1, 0, 0.0f, 0.0f, kInf);
    setRgb(test, 0, 1, 0.25f, 0.0f, 0.0f);
    setRgb(test, 1, 1, 7.0f, 7.0f, 7.0f);
    ErrorReport r = computeError(test, reference);
    EXPECT_EQ(r.nanInfCount, 2u);
    EXPECT_EQ(r.comparedPixels, 1u);
    EXPECT_NEAR(r.rmse, std::sqrt(0.0625 / 3.0), 1e-12);
    EXPECT_DOUBLE_EQ(r.maxAbs, 0.25);
    EXPECT_EQ(r.maxAbsX, 0u);
    EXPECT_EQ(r.maxAbsY, 1u);
    EXPECT_DOUBLE_EQ(r.shareOverThreshold, 1.0);
    EXPECT_TRUE(std::isfinite(r.psnr));
}

TEST(Metrics, SizeMismatchComparesNothing) {
    ErrorReport r = computeError(uniform(2, 2, 1, 1, 1), uniform(2, 3, 0, 0, 0));
    EXPECT_EQ(r.comparedPixels, 0u);
    EXPECT_EQ(r.rmse, 0.0);
    EXPECT_EQ(r.maxAbs, 0.0);
}

TEST(Metrics, TableListsEveryMetricInOrder) {
    const std::vector<MetricInfo>& table = metricTable();
    std::vector<std::string> names;
    for (const MetricInfo& m : table) {
        names.push_back(m.name);
        EXPECT_FALSE(m.description.empty()) << m.name;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"rmse", "psnr", "max_abs", "mean_relative",
                                               "share_over_threshold", "nan_inf",
                                               "worst_pixel_share", "rmse_without_worst_pixel"}));
    ErrorReport r;
    r.rmse = 1;
    r.psnr = 2;
    r.maxAbs = 3;
    r.meanRelative = 4;
    r.shareOverThreshold = 5;
    r.nanInfCount = 6;
    r.worstPixelShare = 7;
    r.rmseWithoutWorstPixel = 8;
    for (size_t i = 0; i < table.size(); ++i)
        EXPECT_EQ(table[i].value(r), double(i + 1)) << table[i].name;
}

TEST(Tonemap, ZeroMapsToZeroAndAlphaToOne) {
    ImageRGBA out = tonemapToDisplay(uniform(1, 1, 0.0f, 0.0f, 0.0f, 0.25f), 0.0f);
    EXPECT_EQ(out.rgba[0], 0.0f);
    EXPECT_EQ(out.rgba[1], 0.0f);
    EXPECT_EQ(out.rgba[2], 0.0f);
    EXPECT_EQ(out.rgba[3], 1.0f);
}

TEST(Tonemap, MonotonicAndSaturatesNearOne) {
    const int n = 2000;
    ImageRGBA ramp(n, 1);
    for (int i = 0; i < n; ++i)
        setRgb(ramp, i, 0, std::pow(10.0f, -4.0f + 8.0f * float(i) / (n - 1)), 0.0f, 0.0f);
    ImageRGBA out = tonemapToDisplay(ramp, 0.0f);
    for (int i = 1; i < n; ++i)
        EXPECT_GE(out.at(i, 0)[0], out.at(i - 1, 0)[0]) << "i=" << i;
    EXPECT_GT(out.at(n - 1, 0)[0], 0.99f);
    EXPECT_LE(out.at(n - 1, 0)[0], 1.0f);
}

TEST(Tonemap, NaNAndNegativeMapToZero) {
    ImageRGBA out = tonemapToDisplay(uniform(1, 1, kNaN, -3.0f, kNaN), 0.0f);
    EXPECT_EQ(out.rgba[0], 0.0f);
    EXPECT_EQ(out.rgba[1], 0.0f);
    EXPECT_EQ(out.rgba[2], 0.0f);
}

TEST(Tonemap, UsesTheSharedOperatorWithExposure) {
    // One EV up doubles the input: same result as the shared operator on 2x the value.
    ImageRGBA out = tonemapToDisplay(uniform(1, 1, 0.1f, 0.4f, 1.5f), 1.0f);
    gpu::vec3 expected = gpu::tonemap(gpu::vec3(0.2f, 0.8f, 3.0f), 0.0f);
    EXPECT_FLOAT_EQ(out.rgba[0], expected.x);
    EXPECT_FLOAT_EQ(out.rgba[1], expected.y);
    EXPECT_FLOAT_EQ(out.rgba[2], expected.z);
}

TEST(Tonemap, AutoExposureMapsLogAverageToKey) {
    // Grey 0.72 has luminance 0.72 = 4 * 0.18: two stops down.
    EXPECT_NEAR(autoExposureEv(uniform(2, 2, 0.72f, 0.72f, 0.72f)), -2.0f, 1e-5f);
    // Log-average of 0.09 and 0.36 is sqrt(0.09 * 0.36) = 0.18: no change. Black, negative
    // and NaN pixels are ignored.
    ImageRGBA mixed = uniform(5, 1, 0.0f, 0.0f, 0.0f);
    setRgb(mixed, 0, 0, 0.09f, 0.09f, 0.09f);
    setRgb(mixed, 1, 0, 0.36f, 0.36f, 0.36f);
    setRgb(mixed, 3, 0, -1.0f, -1.0f, -1.0f);
    setRgb(mixed, 4, 0, kNaN, 1.0f, 1.0f);
    EXPECT_NEAR(autoExposureEv(mixed), 0.0f, 1e-5f);
    // Pure green 1.0 has Rec.709 luminance 0.7152.
    EXPECT_NEAR(autoExposureEv(uniform(1, 1, 0.0f, 1.0f, 0.0f)), std::log2(0.18f / 0.7152f), 1e-5f);
}

TEST(Tonemap, AutoExposureOfBlackIsZero) {
    EXPECT_EQ(autoExposureEv(uniform(3, 3, 0.0f, 0.0f, 0.0f)), 0.0f);
    EXPECT_EQ(autoExposureEv(ImageRGBA()), 0.0f);
}

TEST(ImageDifference, SignedDifferenceIsTestMinusReference) {
    HandPair pair;
    ImageRGBA diff = signedDifference(pair.test, pair.reference);
    ASSERT_EQ(diff.width, 2u);
    ASSERT_EQ(diff.height, 2u);
    EXPECT_EQ(diff.at(1, 0)[0], 0.125f);
    EXPECT_EQ(diff.at(0, 1)[1], -0.25f);
    EXPECT_EQ(diff.at(1, 1)[2], 0.5f);
    for (size_t i = 0; i < diff.pixelCount(); ++i)
        EXPECT_EQ(diff.rgba[i * 4 + 3], 1.0f);
    EXPECT_EQ(signedDifference(uniform(1, 1, 0, 0, 0), uniform(2, 1, 0, 0, 0)).pixelCount(), 0u);
}

namespace {
float lightness(const float* px) {
    return 0.2126f * px[0] + 0.7152f * px[1] + 0.0722f * px[2];
}
} // namespace

TEST(ImageDifference, HeatMapScaleNanAndLegend) {
    // Row 0: |diff| = 0, 0.5, 1, 2 (saturates) with scale 1; row 1: -1 (magnitude counts),
    // NaN, Inf, 0.25.
    ImageRGBA diff = uniform(64, 2, 0.0f, 0.0f, 0.0f);
    setRgb(diff, 1, 0, 0.0f, 0.5f, 0.0f);
    setRgb(diff, 2, 0, 0.0f, 0.0f, 1.0f);
    setRgb(diff, 3, 0, 2.0f, 0.0f, 0.0f);
    setRgb(diff, 0, 1, -1.0f, 0.0f, 0.0f);
    setRgb(diff, 1, 1, kNaN, 0.0f, 0.0f);
    setRgb(diff, 2, 1, 0.0f, kInf, 0.0f);
    setRgb(diff, 3, 1, 0.25f, 0.0f, 0.0f);
    ImageRGBA map = heatMap(diff, 1.0f, 24);
    ASSERT_EQ(map.width, 64u);
    ASSERT_EQ(map.height, 2u + 24u);

    EXPECT_LT(lightness(map.at(0, 0)), 0.02f);                    // 0: near black
    EXPECT_GT(lightness(map.at(1, 0)), lightness(map.at(3, 1)));  // 0.5 brighter than 0.25
    EXPECT_GT(lightness(map.at(2, 0)), lightness(map.at(1, 0)));  // 1 brighter than 0.5
    EXPECT_EQ(std::vector<float>(map.at(3, 0), map.at(3, 0) + 4), // saturates at the top
              std::vector<float>(map.at(2, 0), map.at(2, 0) + 4));
    EXPECT_EQ(std::vector<float>(map.at(0, 1), map.at(0, 1) + 3), // sign does not matter
              std::vector<float>(map.at(2, 0), map.at(2, 0) + 3));
    for (uint32_t x : {1u, 2u}) { // NaN and Inf: magenta
        EXPECT_EQ(map.at(x, 1)[0], 1.0f);
        EXPECT_EQ(map.at(x, 1)[1], 0.0f);
        EXPECT_EQ(map.at(x, 1)[2], 1.0f);
    }
    for (size_t i = 0; i < map.pixelCount(); ++i)
        EXPECT_EQ(map.rgba[i * 4 + 3], 1.0f);

    // Legend: a bar whose lightness rises left to right, and white label pixels below it.
    const uint32_t barY = 2 + 6;
    EXPECT_LT(lightness(map.at(4, barY)), lightness(map.at(32, barY)));
    EXPECT_LT(lightness(map.at(32, barY)), lightness(map.at(59, barY)));
    int whitePixels = 0;
    for (uint32_t y = 2 + 13; y < map.height; ++y)
        for (uint32_t x = 0; x < map.width; ++x)
            whitePixels += map.at(x, y)[0] == 1.0f && map.at(x, y)[1] == 1.0f;
    EXPECT_GT(whitePixels, 10); // "0" and "1" drawn
}

TEST(ImageDifference, HeatMapWithoutLegendAndTinyImages) {
    ImageRGBA map = heatMap(uniform(3, 2, 0.1f, 0.0f, 0.0f), 0.2f, 0);
    EXPECT_EQ(map.height, 2u);
    // Narrower than the labels and a zero scale: clipped, not out of bounds.
    ImageRGBA tiny = heatMap(uniform(1, 1, 0.1f, 0.0f, 0.0f), 0.0f, 24);
    EXPECT_EQ(tiny.height, 25u);
    EXPECT_GT(lightness(tiny.at(0, 0)), 0.9f); // any error saturates on a zero scale
}
