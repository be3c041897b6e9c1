// Our error metrics against OpenImageIO's idiff (Debian's openimageio-tools) on EXR pairs:
// renders written by `triptych compare` (each pipeline against the reference, and the
// pipelines against each other) and constructed pairs (display range, HDR, half floats).
//
// Agreement to 1e-6 relative, although idiff prints only 6 significant digits:
// - idiff's definitions (OIIO ImageBufAlgo::compare): RMS over every channel of the file, alpha
//   included (our images carry alpha 1 in both files, so its mean square is 3/4 of ours over
//   RGB); PSNR = 20 log10(peak / RMS) with peak = max(1, largest value in either image); max
//   error over every channel (alpha adds 0). Each difference is taken in float, ours in
//   double: at most 2^-24 relative per term, 2^-23 allowed.
// - Digits: multiplying both images' RGB by 2^k is exact in float (checked) and multiplies RMS
//   and max error by exactly 2^k. We pick k so the printed value's leading digit is 5..9: six
//   significant digits then resolve it to half a unit of the sixth, <= 1e-6 of the value.
//   The test asserts that resolution as well as the agreement.
// - PSNR: idiff prints it to 6 digits too (5e-5 dB below 100 dB, 5e-4 dB above), checked to
//   that resolution on every call; being 20 log10(peak / RMS) with RMS checked to 1e-6, it
//   agrees to 8.7e-6 dB, below 1e-6 relative for any PSNR over 9 dB.
// Skips with a message when idiff is not installed.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

#include <gtest/gtest.h>
#include <unistd.h>

#include "compare/commands/compare.h"
#include "core/image/image_io.h"
#include "core/image/metrics.h"
#include "temp_path.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;

struct Printed {
    double rms = NAN, psnr = NAN, max = NAN;
    int maxX = -1, maxY = -1;
    std::string text;
};

bool idiffAvailable() {
    return std::system("command -v idiff >/dev/null 2>&1") == 0;
}

Printed runIdiff(const std::string& a, const std::string& b) {
    Printed p;
    std::FILE* pipe = popen(("idiff -fail 0 -warn 0 '" + a + "' '" + b + "' 2>&1").c_str(), "r");
    if (!pipe) return p;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe))
        p.text += buffer;
    pclose(pipe); // non-zero when the images differ; thresholds of 0 make it print the numbers for
                  // any difference
    auto after = [&](const std::string& key) {
        size_t at = p.text.find(key);
        return at == std::string::npos
                   ? double(NAN)
                   : std::strtod(p.text.c_str() + p.text.find('=', at) + 1, nullptr);
    };
    p.rms = after("RMS error");
    p.psnr = after("Peak SNR");
    p.max = after("Max error");
    if (size_t at = p.text.find("@ (", p.text.find("Max error")); at != std::string::npos)
        std::sscanf(p.text.c_str() + at, "@ (%d, %d", &p.maxX, &p.maxY);
    return p;
}

// Half a unit of the sixth significant digit of a value printed with 6 digits.
double halfUnit(double printed) {
    return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(printed))) - 5);
}

// The k for which value * 2^k has a leading decimal digit of 5..9.
int digitShift(double value) {
    int k = 0;
    while (true) {
        double m =
            std::ldexp(value, k) / std::pow(10.0, std::floor(std::log10(std::ldexp(value, k))));
        if (m >= 5.0) return k;
        ++k;
    }
}

ImageRGBA scaledRgb(const ImageRGBA& image, int k) {
    ImageRGBA out = image;
    for (size_t i = 0; i < out.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            float& v = out.rgba[i * 4 + c];
            v = std::ldexp(v, k);
            EXPECT_EQ(std::ldexp(v, -k), image.rgba[i * 4 + c])
                << "scaling by 2^" << k << " is not exact";
        }
    return out;
}

float largestRgb(const ImageRGBA& a, const ImageRGBA& b) {
    float m = 0.0f;
    for (const ImageRGBA* image : {&a, &b})
        for (size_t i = 0; i < image->pixelCount(); ++i)
            for (int c = 0; c < 3; ++c)
                m = std::max(m, image->rgba[i * 4 + c]);
    return m;
}

// Compares our metrics of (a, b) with idiff's on the files as given (k = 0) and on copies
// scaled for the digits of RMS and of the max error.
void crossCheck(const std::string& aPath, const std::string& bPath, const std::string& scratch) {
    SCOPED_TRACE(aPath + " vs " + bPath);
    Result<ImageRGBA> a = readExr(aPath), b = readExr(bPath);
    ASSERT_TRUE(a.ok() && b.ok());
    for (size_t i = 0; i < a->pixelCount(); ++i) // the 3/4 below needs equal alpha
        ASSERT_EQ(a->rgba[i * 4 + 3], b->rgba[i * 4 + 3]) << "alpha differs at pixel " << i;
    const ErrorReport ours = computeError(*a, *b);
    ASSERT_EQ(ours.nanInfCount, 0u);
    ASSERT_GT(ours.rmse, 0.0) << "identical images: nothing to compare";
    const double rms = ours.rmse * std::sqrt(0.75); // over RGBA, alpha adding 0
    const float largest = largestRgb(*a, *b);

    std::set<int> shifts = {0, digitShift(rms), digitShift(ours.maxAbs)};
    for (int k : shifts) {
        std::string ap = aPath, bp = bPath;
        if (k != 0) {
            ap = scratch + "/scaled_a.exr";
            bp = scratch + "/scaled_b.exr";
            ASSERT_TRUE(writeExr(ap, scaledRgb(*a, k), ExrPixelType::Float).ok());
            ASSERT_TRUE(writeExr(bp, scaledRgb(*b, k), ExrPixelType::Float).ok());
        }
        const Printed p = runIdiff(ap, bp);
        SCOPED_TRACE("2^" + std::to_string(k) + "\n" + p.text);
        // Our metric with idiff's PSNR peak for these files.
        MetricsOptions options;
        options.psnrPeak = std::max(1.0f, std::ldexp(largest, k));
        const double psnr = computeError(scaledRgb(*a, k), scaledRgb(*b, k), options).psnr -
                            10.0 * std::log10(0.75);
        const double want[] = {std::ldexp(rms, k), std::ldexp(ours.maxAbs, k), psnr};
        const double got[] = {p.rms, p.max, p.psnr};
        const char* names[] = {"RMS", "max", "PSNR"};
        for (int m = 0; m < 3; ++m) {
            ASSERT_TRUE(std::isfinite(got[m])) << names[m];
            EXPECT_NEAR(got[m], want[m], halfUnit(got[m]) + std::abs(want[m]) * 0x1p-23)
                << names[m];
        }
        if (k == digitShift(rms)) {
            EXPECT_LE(halfUnit(p.rms) / std::ldexp(rms, k), 1e-6) << "RMS resolved to 1e-6";
        }
        if (k == digitShift(ours.maxAbs)) {
            EXPECT_LE(halfUnit(p.max) / std::ldexp(ours.maxAbs, k), 1e-6) << "max resolved to 1e-6";
        }
        EXPECT_EQ(p.maxX, int(ours.maxAbsX));
        EXPECT_EQ(p.maxY, int(ours.maxAbsY));
    }
}

uint32_t nextRandom(uint32_t& state) {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
}

// A reference with values in [0, range) and a test that differs by up to `noise` (relative
// when `relative`), alpha 1 in both.
std::pair<ImageRGBA, ImageRGBA> constructedPair(float range, float noise, bool relative,
                                                uint32_t seed) {
    ImageRGBA ref(40, 24), test(40, 24);
    for (size_t i = 0; i < ref.pixelCount(); ++i)
        for (int c = 0; c < 4; ++c) {
            float v = c == 3 ? 1.0f : range * float(nextRandom(seed)) / 16777216.0f;
            float n = c == 3 ? 0.0f : noise * (2.0f * float(nextRandom(seed)) / 16777216.0f - 1.0f);
            ref.rgba[i * 4 + c] = v;
            test.rgba[i * 4 + c] = v + (relative ? v * n : n);
        }
    return {test, ref};
}

std::string freshCreatedDir(const std::string& name) {
    std::string p = freshDir(name);
    fs::create_directories(p);
    return p;
}

} // namespace

TEST(IdiffCrossCheck, ConstructedPairs) {
    if (!idiffAvailable())
        GTEST_SKIP() << "idiff (Debian openimageio-tools) not on PATH: metrics not cross-checked";
    const std::string dir = freshCreatedDir("idiff_constructed");
    struct Case {
        const char* name;
        float range, noise;
        bool relative;
        ExrPixelType type;
    };
    for (const Case& c : {Case{"display", 1.0f, 0.01f, false, ExrPixelType::Float},
                          Case{"hdr", 40.0f, 1e-4f, true, ExrPixelType::Float},
                          Case{"half", 8.0f, 0.05f, true, ExrPixelType::Half}}) {
        auto [test, ref] = constructedPair(c.range, c.noise, c.relative, 7);
        const std::string a = dir + "/" + c.name + "_test.exr", b = dir + "/" + c.name + "_ref.exr";
        ASSERT_TRUE(writeExr(a, test, c.type).ok());
        ASSERT_TRUE(writeExr(b, ref, c.type).ok());
        crossCheck(a, b, dir);
    }
    fs::remove_all(dir);
}

// The files `triptych compare` writes: every pipeline against the reference and against each other.
TEST(IdiffCrossCheck, CompareRenders) {
    if (!idiffAvailable())
        GTEST_SKIP() << "idiff (Debian openimageio-tools) not on PATH: metrics not cross-checked";
    const std::string dir = freshCreatedDir("idiff_renders");
    cli::CompareOptions o;
    o.scene.scene = "builtin:courtyard-small";
    o.scene.lightCount = 16;
    o.view.resolution = "96x54";
    o.frames = 1;
    o.warmup = 0;
    o.out = dir + "/out";
    ASSERT_EQ(cli::runCompare(o), 0);
    std::vector<std::string> names;
    for (const RendererEntry& e : registeredRenderers())
        if (e.name != "reference") names.push_back(e.name);
    for (size_t i = 0; i < names.size(); ++i) {
        crossCheck(o.out + "/" + names[i] + ".exr", o.out + "/reference.exr", dir);
        for (size_t k = i + 1; k < names.size(); ++k)
            crossCheck(o.out + "/" + names[i] + ".exr", o.out + "/" + names[k] + ".exr", dir);
    }
    fs::remove_all(dir);
}

} // namespace tp::test
