// FLIP and HDR-FLIP: the parts on hand-checkable cases (colour transforms, filters, pooling,
// the fast maths), the whole on identical images and a one-pixel spike, and the cross-check
// against the pooled values NVIDIA's reference tool printed for the pairs in shared/flip
// (MANIFEST.txt there says how they were made and measured).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "compare/measure/flip_measure.h"
#include "core/image/difference.h"
#include "core/image/flip.h"
#include "core/image/flip_color.h"
#include "core/image/flip_filter.h"
#include "core/image/image_io.h"

using namespace tp;

namespace {

ImageRGBA uniform(uint32_t w, uint32_t h, float v) {
    ImageRGBA image(w, h);
    for (size_t i = 0; i < image.pixelCount(); ++i)
        for (int c = 0; c < 4; ++c)
            image.rgba[i * 4 + size_t(c)] = c == 3 ? 1.0f : v;
    return image;
}

// A deterministic busy image: gradients, stripes and a little noise.
ImageRGBA pattern(uint32_t w, uint32_t h, float gain) {
    ImageRGBA image(w, h);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> noise(0.0f, 0.05f);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            float* px = image.at(x, y);
            const float stripe = (x / 5 + y / 7) % 2 ? 0.6f : 0.2f;
            px[0] = gain * (stripe + noise(rng));
            px[1] = gain * (float(x) / float(w) + noise(rng)) * 0.8f;
            px[2] = gain * (float(y) / float(h) + noise(rng)) * 0.5f;
            px[3] = 1.0f;
        }
    return image;
}

} // namespace

TEST(Flip, ColourTransformsRoundTrip) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 1000; ++i) {
        const flip::Vec3 rgb{u(rng), u(rng), u(rng)};
        const flip::Vec3 back = flip::xyzToLinearRgb(flip::linearRgbToXyz(rgb));
        EXPECT_NEAR(back.x, rgb.x, 1e-5f);
        EXPECT_NEAR(back.y, rgb.y, 1e-5f);
        EXPECT_NEAR(back.z, rgb.z, 1e-5f);
        const flip::Vec3 xyz = flip::linearRgbToXyz(rgb);
        const flip::Vec3 xyz2 = flip::ycxczToXyz(flip::xyzToYcxcz(xyz));
        EXPECT_NEAR(xyz2.x, xyz.x, 1e-5f);
        EXPECT_NEAR(xyz2.y, xyz.y, 1e-5f);
        EXPECT_NEAR(xyz2.z, xyz.z, 1e-5f);
    }
    // White is the reference white: YyCxCz (100, 0, 0) and L*a*b* (100, 0, 0).
    const flip::Vec3 white = flip::xyzToYcxcz(flip::linearRgbToXyz({1, 1, 1}));
    EXPECT_NEAR(white.x, 100.0f, 1e-4f);
    EXPECT_NEAR(white.y, 0.0f, 1e-4f);
    EXPECT_NEAR(white.z, 0.0f, 1e-4f);
    const flip::Vec3 lab = flip::linearRgbToHuntLab({1, 1, 1});
    EXPECT_NEAR(lab.x, 100.0f, 1e-4f);
    EXPECT_NEAR(lab.y, 0.0f, 1e-4f);
    // sRGB decode: the two branches meet at 0.04045, and 1 stays 1.
    EXPECT_NEAR(flip::srgbToLinear(0.04045f), 0.04045f / 12.92f, 1e-7f);
    EXPECT_NEAR(flip::srgbToLinear(1.0f), 1.0f, 1e-6f);
    // HyAB: |dL| + Euclidean in (a, b).
    EXPECT_FLOAT_EQ(flip::hyab({50, 3, 0}, {47, 0, 4}), 3.0f + 5.0f);
}

TEST(Flip, FastMathMatchesLibm) {
    for (float x = 1e-6f; x < 2.0f; x *= 1.01f) {
        EXPECT_NEAR(flip::fastCbrt(x), std::cbrt(x), 2e-7f * std::cbrt(x)) << x;
        EXPECT_NEAR(flip::fastPow(x, 0.7f), std::pow(x, 0.7f), 1e-6f * std::pow(x, 0.7f)) << x;
    }
    for (float x = 1e-3f; x < 400.0f; x *= 1.05f)
        EXPECT_NEAR(flip::fastPow(x, 0.7f), std::pow(x, 0.7f), 1e-6f * std::pow(x, 0.7f)) << x;
    EXPECT_EQ(flip::fastPow(0.0f, 0.0f), 1.0f); // as std::pow: FLIP's colour 0 with feature 1
    EXPECT_EQ(flip::fastPow(0.0f, 0.3f), 0.0f);
    EXPECT_NEAR(flip::fastPow(0.5f, 1.0f), 0.5f, 1e-7f);
}

TEST(Flip, FiltersIntegrateToOne) {
    const float ppd = flipPixelsPerDegree();
    EXPECT_NEAR(ppd, 3840.0f * 3.14159265f / 180.0f, 1e-3f);
    const flip::CsfFilters csf = flip::makeCsfFilters(ppd);
    // ceil(3 sqrt(0.04 / (2 pi^2)) 67.02) = ceil(9.05) = 10.
    EXPECT_EQ(csf.achromatic.gaussians[0].radius, 10);
    for (const flip::CsfFilter* f : {&csf.achromatic, &csf.redGreen, &csf.blueYellow}) {
        double weightSum = 0.0, kernel2d = 0.0;
        for (size_t i = 0; i < f->gaussians.size(); ++i) {
            double sum = 0.0;
            for (float t : f->gaussians[i].taps)
                sum += t;
            EXPECT_NEAR(sum, 1.0, 1e-6);
            weightSum += f->weights[i];
            kernel2d += f->weights[i] * sum * sum; // the 2D kernel: sum_i w_i g_i(x) g_i(y)
        }
        EXPECT_NEAR(weightSum, 1.0, 1e-6);
        EXPECT_NEAR(kernel2d, 1.0, 1e-6);
    }
    EXPECT_EQ(csf.blueYellow.gaussians.size(), 2u);

    const flip::FeatureFilters feat = flip::makeFeatureFilters(ppd);
    EXPECT_EQ(feat.gaussian.radius, 9); // sigma = 0.5 * 0.082 * 67.02 = 2.75, ceil(3 sigma)
    double g = 0.0;
    for (float t : feat.gaussian.taps)
        g += t;
    EXPECT_NEAR(g, 1.0, 1e-6);
    for (const flip::Kernel* k : {&feat.firstDerivative, &feat.secondDerivative}) {
        double positive = 0.0, negative = 0.0;
        for (float t : k->taps)
            (t > 0 ? positive : negative) += t;
        EXPECT_NEAR(positive, 1.0, 1e-6);
        EXPECT_NEAR(negative, -1.0, 1e-6);
    }
}

TEST(Flip, PoolingOnHandComputedMap) {
    // Sorted 0, 0.25, 0.25, 0.5: total 1, running sums 0, 0.25, 0.5, 1. The weighted quartile
    // p is the first value whose running sum reaches p: Q1 0.25, median 0.25, Q3 0.5.
    ImageR32 map{2, 2, {0.5f, 0.0f, 0.25f, 0.25f}};
    FlipStats s = poolFlip(map);
    EXPECT_DOUBLE_EQ(s.mean, 0.25);
    EXPECT_DOUBLE_EQ(s.min, 0.0);
    EXPECT_DOUBLE_EQ(s.max, 0.5);
    EXPECT_DOUBLE_EQ(s.weightedQ1, 0.25);
    EXPECT_DOUBLE_EQ(s.weightedMedian, 0.25);
    EXPECT_DOUBLE_EQ(s.weightedQ3, 0.5);
}

TEST(Flip, TonemapperAndExposures) {
    EXPECT_EQ(flipTonemapAces(0.0f), 0.0f);
    EXPECT_EQ(flipTonemapAces(1e6f), 1.0f);
    for (float x = 0.01f; x < 10.0f; x *= 1.5f)
        EXPECT_LT(flipTonemapAces(x), flipTonemapAces(1.5f * x));
    // Constant luminance 1: max = median, so start = stop = log2(x) where x tonemaps to 0.85,
    // and two exposures (the minimum).
    FlipExposures e = flipAutoExposures(uniform(8, 8, 1.0f));
    EXPECT_NEAR(flipTonemapAces(std::exp2(e.start)), 0.85f, 1e-5f);
    EXPECT_FLOAT_EQ(e.start, e.stop);
    EXPECT_EQ(e.count, 2);
}

TEST(Flip, IdenticalImagesGiveExactlyZero) {
    const ImageRGBA image = pattern(64, 48, 1.0f);
    FlipResult ldr = ldrFlip(image, image, flipPixelsPerDegree());
    ASSERT_EQ(ldr.map.r.size(), image.pixelCount());
    for (float v : ldr.map.r)
        ASSERT_EQ(v, 0.0f);
    EXPECT_EQ(ldr.stats.mean, 0.0);
    EXPECT_EQ(ldr.stats.max, 0.0);
    const ImageRGBA hdr = pattern(64, 48, 20.0f);
    FlipResult h = hdrFlip(hdr, hdr, flipPixelsPerDegree());
    for (float v : h.map.r)
        ASSERT_EQ(v, 0.0f);
    EXPECT_EQ(h.stats.max, 0.0);
}

TEST(Flip, DifferentSizesGiveAnEmptyMap) {
    EXPECT_TRUE(ldrFlip(uniform(4, 4, 0.5f), uniform(4, 5, 0.5f), 67.0f).map.r.empty());
    EXPECT_TRUE(hdrFlip(uniform(4, 4, 0.5f), uniform(5, 4, 0.5f), 67.0f).map.r.empty());
}

TEST(Flip, NonFiniteInputIsEvaluatedAsBlack) {
    ImageRGBA test = uniform(16, 16, 0.5f), black = uniform(16, 16, 0.5f);
    test.at(8, 8)[1] = std::numeric_limits<float>::quiet_NaN();
    black.at(8, 8)[1] = 0.0f;
    FlipResult a = hdrFlip(test, uniform(16, 16, 0.5f), 67.0f);
    FlipResult b = hdrFlip(black, uniform(16, 16, 0.5f), 67.0f);
    EXPECT_EQ(a.map.r, b.map.r);
    EXPECT_GT(a.stats.max, 0.0);
}

// A white pixel on mid grey: the error peaks at the spike, falls off with distance and is
// symmetric about it (the filters are), and it stays near the spike (within the filter radii).
TEST(Flip, OnePixelSpikeGivesTheLocalMaximum) {
    const uint32_t n = 41, c = 20;
    ImageRGBA reference = uniform(n, n, 0.5f), test = reference;
    float* px = test.at(c, c);
    px[0] = px[1] = px[2] = 1.0f;
    FlipResult r = ldrFlip(test, reference, flipPixelsPerDegree());
    auto at = [&](uint32_t x, uint32_t y) { return r.map.r[size_t(y) * n + x]; };
    EXPECT_FLOAT_EQ(float(r.stats.max), at(c, c));
    EXPECT_GT(at(c, c), 0.1f);
    for (uint32_t d = 1; d <= 3; ++d) {
        EXPECT_LT(at(c + d, c), at(c + d - 1, c)) << d;
        EXPECT_FLOAT_EQ(at(c + d, c), at(c - d, c));
        EXPECT_FLOAT_EQ(at(c, c + d), at(c, c - d));
        EXPECT_NEAR(at(c + d, c), at(c, c + d), 1e-6f);
    }
    // Beyond the widest kernel (CSF radius 10 + feature radius 9) nothing changed.
    EXPECT_EQ(at(0, 0), 0.0f);
}

TEST(Flip, ErrorMapIsMagmaWithALegend) {
    ImageR32 map{2, 1, {0.0f, 1.0f}};
    ImageRGBA png = flipErrorMap(map, 0);
    ASSERT_EQ(png.width, 2u);
    ASSERT_EQ(png.height, 1u);
    // magma's ends: #000004 and #fcfdbf.
    EXPECT_NEAR(png.at(0, 0)[2], 4.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(png.at(1, 0)[0], 252.0f / 255.0f, 1e-6f);
    EXPECT_NEAR(png.at(1, 0)[2], 191.0f / 255.0f, 1e-6f);
    EXPECT_EQ(flipErrorMap(ImageR32{64, 8, std::vector<float>(64 * 8, 0.5f)}, 24).height, 8u + 24u);
}

// compare's FLIP: identical images measure 0 on both inputs; the distance option is checked.
TEST(Flip, CompareMeasureAndDistanceOption) {
    const ImageRGBA image = pattern(40, 30, 3.0f);
    cli::FlipMeasure m = cli::measureFlip(image, image, 0.0f, 0.7f, /*keepMaps=*/true);
    ASSERT_TRUE(m.measured);
    EXPECT_EQ(m.ldr.max, 0.0);
    EXPECT_EQ(m.hdr.max, 0.0);
    EXPECT_EQ(m.hdrMap.r.size(), image.pixelCount());
    EXPECT_TRUE(cli::flipJson(m)["hdr"]["exposures"].get<int>() >= 2);
    EXPECT_THROW(cli::checkFlipDistance(0.05f), cli::UsageError);
    EXPECT_THROW(cli::checkFlipDistance(11.0f), cli::UsageError);
    EXPECT_NO_THROW(cli::checkFlipDistance(0.7f));
    // Twice the distance, twice the pixels per degree.
    EXPECT_NEAR(flipPixelsPerDegree(1.4f), 2.0f * flipPixelsPerDegree(0.7f), 1e-3f);
}

// ---- Cross-check against NVIDIA's reference implementation (v1.6, default options) -------

namespace {

const std::string kFlipData = TP_SHARED_FLIP;

bool haveFlipData() {
    return std::filesystem::exists(kFlipData + "/MANIFEST.txt");
}

struct Published {
    double mean, median, q1, q3, min, max;
};

void expectPooled(const FlipStats& s, const Published& p) {
    // The figures' own tolerance is 1e-4 (float maths, a different order of operations and
    // separable filters on both sides); ours land within ~1e-6 (docs/report.md).
    EXPECT_NEAR(s.mean, p.mean, 1e-4);
    EXPECT_NEAR(s.weightedMedian, p.median, 1e-4);
    EXPECT_NEAR(s.weightedQ1, p.q1, 1e-4);
    EXPECT_NEAR(s.weightedQ3, p.q3, 1e-4);
    EXPECT_NEAR(s.min, p.min, 1e-4);
    EXPECT_NEAR(s.max, p.max, 1e-4);
}

} // namespace

TEST(FlipCrossCheck, LdrCropPairMatchesReferenceTool) {
    if (!haveFlipData()) GTEST_SKIP() << "no FLIP cross-check data at " << kFlipData;
    Result<ImageRGBA> ref = readPng(kFlipData + "/derived/crop_ldr_reference.png");
    Result<ImageRGBA> test = readPng(kFlipData + "/derived/crop_ldr_test.png");
    ASSERT_TRUE(ref) << ref.error();
    ASSERT_TRUE(test) << test.error();
    FlipResult r = ldrFlip(*test, *ref, flipPixelsPerDegree());
    expectPooled(r.stats,
                 {0.067184024, 0.080972515, 0.055151936, 0.124855176, 0.000585206, 0.618490040});
}

TEST(FlipCrossCheck, HdrCropPairMatchesReferenceTool) {
    if (!haveFlipData()) GTEST_SKIP() << "no FLIP cross-check data at " << kFlipData;
    Result<ImageRGBA> ref = readExr(kFlipData + "/derived/crop_hdr_reference.exr");
    Result<ImageRGBA> test = readExr(kFlipData + "/derived/crop_hdr_test.exr");
    ASSERT_TRUE(ref) << ref.error();
    ASSERT_TRUE(test) << test.error();
    FlipResult r = hdrFlip(*test, *ref, flipPixelsPerDegree());
    // The tool chose start -4.1028943, stop 5.0382185, 10 exposures.
    EXPECT_NEAR(r.exposures.start, -4.1028943f, 1e-5f);
    EXPECT_NEAR(r.exposures.stop, 5.0382185f, 1e-5f);
    EXPECT_EQ(r.exposures.count, 10);
    expectPooled(r.stats,
                 {0.179226205, 0.272096336, 0.223617271, 0.318868250, 0.000497353, 0.724949777});
}

TEST(FlipCrossCheck, IdenticalReferenceImageIsZero) {
    if (!haveFlipData()) GTEST_SKIP() << "no FLIP cross-check data at " << kFlipData;
    Result<ImageRGBA> ref = readPng(kFlipData + "/reference.png");
    ASSERT_TRUE(ref) << ref.error();
    FlipResult r = ldrFlip(*ref, *ref, flipPixelsPerDegree());
    EXPECT_EQ(r.stats.mean, 0.0);
    EXPECT_EQ(r.stats.max, 0.0);
}
