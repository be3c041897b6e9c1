// EXR and PNG writers, read back through our reader, through OpenEXR directly and through
// stb_image, plus a cross-check of our metrics against OpenImageIO's idiff.
#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
// Debian's libstb exports stbi_load, so no STB_IMAGE_IMPLEMENTATION here.
#include <stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>

#include "core/image/image_io.h"
#include "core/image/metrics.h"

using namespace tp;
namespace fs = std::filesystem;

namespace {

// A fresh directory per test, removed afterwards.
struct ScratchDir {
    fs::path path;
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path = fs::temp_directory_path() / ("triptych_image_io_" + std::to_string(getpid()) + "_" +
                                            info->test_suite_name() + "_" + info->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~ScratchDir() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

// Deterministic values covering HDR range, negatives and tiny numbers.
ImageRGBA testImage(uint32_t w, uint32_t h, uint32_t seed) {
    ImageRGBA image(w, h);
    uint32_t state = seed * 747796405u + 2891336453u;
    for (float& v : image.rgba) {
        state = state * 1664525u + 1013904223u;
        float unit = float(state >> 8) / float(1u << 24); // [0,1)
        v = unit;
    }
    image.at(0, 0)[0] = 1000.0f;
    image.at(0, 0)[1] = -2.5f;
    image.at(0, 0)[2] = 1e-3f;
    return image;
}

// Writes R, G, B float channels only (no alpha), as other renderers often do.
void writeRgbOnlyExr(const std::string& path, const ImageRGBA& image) {
    Imf::Header header(int(image.width), int(image.height));
    const char* names[3] = {"R", "G", "B"};
    for (const char* name : names)
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer fb;
    const size_t xStride = 4 * sizeof(float);
    for (int c = 0; c < 3; ++c)
        fb.insert(names[c], Imf::Slice(Imf::FLOAT, (char*)(image.rgba.data() + c), xStride,
                                       xStride * image.width));
    file.setFrameBuffer(fb);
    file.writePixels(int(image.height));
}

bool isOneLine(const std::string& s) {
    return s.find('\n') == std::string::npos;
}

} // namespace

TEST(Exr, FloatRoundTripIsExact) {
    ScratchDir dir;
    ImageRGBA image = testImage(7, 5, 1);
    ASSERT_TRUE(writeExr(dir.file("a.exr"), image, ExrPixelType::Float).ok());
    Result<ImageRGBA> back = readExr(dir.file("a.exr"));
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(back->width, 7u);
    EXPECT_EQ(back->height, 5u);
    EXPECT_EQ(back->rgba, image.rgba);
    EXPECT_FALSE(fs::exists(dir.file("a.exr.partial")));
}

TEST(Exr, HalfRoundTripWithinHalfPrecision) {
    ScratchDir dir;
    ImageRGBA image = testImage(9, 4, 2);
    ASSERT_TRUE(writeExr(dir.file("h.exr"), image, ExrPixelType::Half).ok());
    Result<ImageRGBA> back = readExr(dir.file("h.exr"));
    ASSERT_TRUE(back.ok()) << back.error();
    ASSERT_EQ(back->rgba.size(), image.rgba.size());
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        // Half has 11 significant bits: relative rounding error <= 2^-11 for normal values;
        // below 2^-14 the step is absolute (2^-24).
        float tolerance = std::max(std::abs(image.rgba[i]) * 0x1p-11f, 0x1p-24f);
        EXPECT_NEAR(back->rgba[i], image.rgba[i], tolerance) << "i=" << i;
    }
    EXPECT_EQ(back->rgba[0], 1000.0f); // exactly representable in half
}

TEST(Exr, OpenEXRReadsOurFileDirectly) {
    ScratchDir dir;
    ImageRGBA image = testImage(6, 3, 3);
    ASSERT_TRUE(writeExr(dir.file("d.exr"), image, ExrPixelType::Half).ok());
    Imf::RgbaInputFile file(dir.file("d.exr").c_str());
    const Imath::Box2i dw = file.dataWindow();
    ASSERT_EQ(dw.max.x - dw.min.x + 1, 6);
    ASSERT_EQ(dw.max.y - dw.min.y + 1, 3);
    EXPECT_EQ(file.channels(), Imf::WRITE_RGBA);
    std::vector<Imf::Rgba> pixels(6 * 3);
    file.setFrameBuffer(pixels.data(), 1, 6);
    file.readPixels(dw.min.y, dw.max.y);
    for (uint32_t y = 0; y < 3; ++y) {
        for (uint32_t x = 0; x < 6; ++x) {
            const Imf::Rgba& p = pixels[y * 6 + x];
            const float* want = image.at(x, y);
            float tol = std::max(std::abs(want[0]) * 0x1p-11f, 0x1p-24f);
            EXPECT_NEAR(float(p.r), want[0], tol);
            EXPECT_NEAR(float(p.a), want[3], 1e-3f);
        }
    }
}

TEST(Exr, RgbWithoutAlphaReadsOpaque) {
    ScratchDir dir;
    ImageRGBA image = testImage(4, 4, 4);
    writeRgbOnlyExr(dir.file("rgb.exr"), image);
    Result<ImageRGBA> back = readExr(dir.file("rgb.exr"));
    ASSERT_TRUE(back.ok()) << back.error();
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(back->rgba[i * 4 + c], image.rgba[i * 4 + c]);
        EXPECT_EQ(back->rgba[i * 4 + 3], 1.0f);
    }
}

TEST(Exr, WriteToMissingDirectoryFailsAndLeavesNoFile) {
    ScratchDir dir;
    const std::string path = dir.file("no/such/dir/out.exr");
    Status status = writeExr(path, testImage(2, 2, 5), ExrPixelType::Half);
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().rfind(path + ": ", 0), 0u) << status.error();
    EXPECT_TRUE(isOneLine(status.error())) << status.error();
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".partial"));
}

TEST(Exr, ReadErrorsNameTheFile) {
    ScratchDir dir;
    const std::string missing = dir.file("missing.exr");
    Result<ImageRGBA> r = readExr(missing);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().rfind(missing + ": ", 0), 0u) << r.error();
    EXPECT_TRUE(isOneLine(r.error())) << r.error();

    const std::string garbage = dir.file("garbage.exr");
    std::ofstream(garbage) << "this is not an EXR file\n";
    r = readExr(garbage);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().rfind(garbage + ": ", 0), 0u) << r.error();
    EXPECT_TRUE(isOneLine(r.error())) << r.error();
}

TEST(Exr, LuminanceOnlyFileIsRejected) {
    ScratchDir dir;
    const std::string path = dir.file("y.exr");
    {
        Imf::Header header(2, 2);
        header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path.c_str(), header);
        std::vector<float> y(4, 0.5f);
        Imf::FrameBuffer fb;
        fb.insert("Y", Imf::Slice(Imf::FLOAT, (char*)y.data(), sizeof(float), 2 * sizeof(float)));
        file.setFrameBuffer(fb);
        file.writePixels(2);
    }
    Result<ImageRGBA> r = readExr(path);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("'R'"), std::string::npos) << r.error();
}

TEST(Png, WrittenAndDecodedBack) {
    ScratchDir dir;
    // Display values and the byte each must become (round(v * 255), clamped; NaN -> 0).
    const float values[] = {0.0f,   1.0f,    0.5f,
                            0.25f,  0.2f,    1.5f,
                            -0.3f,  0.9999f, std::numeric_limits<float>::quiet_NaN(),
                            0.002f, 0.998f,  0.6f};
    const int bytes[] = {0, 255, 128, 64, 51, 255, 0, 255, 0, 1, 254, 153};
    ImageRGBA image(3, 1);
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c)
            image.rgba[i * 4 + c] = values[i * 4 + c];
        image.rgba[i * 4 + 3] = values[i * 4 + 3];
    }
    for (bool keepAlpha : {false, true}) {
        const std::string path = dir.file(keepAlpha ? "alpha.png" : "opaque.png");
        Status status = writePng(path, image, keepAlpha);
        ASSERT_TRUE(status.ok()) << status.error();
        int w = 0, h = 0, n = 0;
        unsigned char* decoded = stbi_load(path.c_str(), &w, &h, &n, 4);
        ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
        EXPECT_EQ(w, 3);
        EXPECT_EQ(h, 1);
        for (int i = 0; i < 12; ++i) {
            int want = (i % 4 == 3 && !keepAlpha) ? 255 : bytes[i];
            EXPECT_EQ(int(decoded[i]), want) << "byte " << i << " keepAlpha " << keepAlpha;
        }
        stbi_image_free(decoded);
        EXPECT_FALSE(fs::exists(path + ".partial"));
    }
}

TEST(Png, WriteToMissingDirectoryFailsAndLeavesNoFile) {
    ScratchDir dir;
    const std::string path = dir.file("nope/out.png");
    Status status = writePng(path, ImageRGBA(2, 2));
    ASSERT_FALSE(status.ok());
    EXPECT_EQ(status.error().rfind(path + ": ", 0), 0u) << status.error();
    EXPECT_FALSE(fs::exists(path));
    EXPECT_FALSE(fs::exists(path + ".partial"));
}

namespace {

struct IdiffNumbers {
    double mean = NAN, rms = NAN, psnr = NAN, max = NAN;
    int maxX = -1, maxY = -1;
};

std::optional<std::string> runCommand(const std::string& command) {
    std::FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return std::nullopt;
    std::string out;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe))
        out += buffer;
    pclose(pipe); // idiff exits non-zero when the images differ, which they do here
    return out;
}

// Parses lines such as "  RMS error = 0.144338" and "  Max error  = 0.25 @ (0, 0, G) ...".
IdiffNumbers parseIdiff(const std::string& text) {
    IdiffNumbers n;
    auto valueAfter = [&](const std::string& key) {
        size_t at = text.find(key);
        if (at == std::string::npos) return double(NAN);
        size_t eq = text.find('=', at);
        return std::strtod(text.c_str() + eq + 1, nullptr);
    };
    n.mean = valueAfter("Mean error");
    n.rms = valueAfter("RMS error");
    n.psnr = valueAfter("Peak SNR");
    n.max = valueAfter("Max error");
    size_t paren = text.find("@ (", text.find("Max error"));
    if (paren != std::string::npos)
        std::sscanf(text.c_str() + paren, "@ (%d, %d", &n.maxX, &n.maxY);
    return n;
}

bool idiffAvailable() {
    return std::system("command -v idiff >/dev/null 2>&1") == 0;
}

// Mean |t-r| over pixels and RGB: idiff's "Mean error", not one of our metrics.
double meanAbs(const ImageRGBA& a, const ImageRGBA& b) {
    double sum = 0;
    for (size_t i = 0; i < a.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
            sum += std::abs(double(a.rgba[i * 4 + c]) - double(b.rgba[i * 4 + c]));
    return sum / double(a.pixelCount() * 3);
}

// OpenImageIO's compare() uses max(1, largest value in either image, any channel) as the
// PSNR peak rather than a fixed 1; we pass the same peak explicitly.
double oiioPeak(const ImageRGBA& a, const ImageRGBA& b) {
    float peak = 1.0f;
    for (const ImageRGBA* image : {&a, &b})
        for (float v : image->rgba)
            peak = std::max(peak, v);
    return peak;
}

// idiff prints 6 significant digits.
void expectSixDigits(double ours, double theirs, const char* what) {
    EXPECT_NEAR(theirs, ours, std::abs(ours) * 1e-5 + 1e-12) << what;
}

} // namespace

// idiff averages over every channel in the file. On RGB-only files that is exactly our
// definition; with an identical alpha channel it divides the same squared sum by 4 instead
// of 3 channels, so its MSE is 3/4 of ours and its PSNR 10 log10(4/3) = 1.249 dB higher.
// Its PSNR peak is not 1 but the largest value present (see oiioPeak).
TEST(MetricsIdiff, AgreesWithOpenImageIO) {
    if (!idiffAvailable()) GTEST_SKIP() << "idiff (openimageio-tools) not on PATH";
    ScratchDir dir;
    ImageRGBA reference = testImage(16, 8, 10);
    ImageRGBA test = testImage(16, 8, 11);
    reference.at(0, 0)[0] = test.at(0, 0)[0] = 0.5f; // keep the data in [0,1] for PSNR
    reference.at(0, 0)[1] = test.at(0, 0)[1] = 0.5f;
    for (ImageRGBA* image : {&reference, &test})
        for (size_t i = 0; i < image->pixelCount(); ++i)
            image->rgba[i * 4 + 3] = 1.0f;
    test.at(5, 3)[2] = reference.at(5, 3)[2] + 1.5f; // a unique maximum at (5, 3)

    for (bool withAlpha : {false, true}) {
        const std::string a = dir.file(withAlpha ? "test_rgba.exr" : "test_rgb.exr");
        const std::string b = dir.file(withAlpha ? "ref_rgba.exr" : "ref_rgb.exr");
        if (withAlpha) {
            ASSERT_TRUE(writeExr(a, test, ExrPixelType::Float).ok());
            ASSERT_TRUE(writeExr(b, reference, ExrPixelType::Float).ok());
        } else {
            writeRgbOnlyExr(a, test);
            writeRgbOnlyExr(b, reference);
        }
        Result<ImageRGBA> ta = readExr(a), rb = readExr(b);
        ASSERT_TRUE(ta.ok() && rb.ok());
        MetricsOptions options;
        options.psnrPeak = float(oiioPeak(*ta, *rb));
        ErrorReport ours = computeError(*ta, *rb, options);

        std::optional<std::string> out = runCommand("idiff -a '" + a + "' '" + b + "' 2>&1");
        ASSERT_TRUE(out.has_value());
        IdiffNumbers theirs = parseIdiff(*out);
        SCOPED_TRACE((withAlpha ? "RGBA files\n" : "RGB files\n") + *out);

        const double channelShare = withAlpha ? 3.0 / 4.0 : 1.0;
        expectSixDigits(ours.rmse * std::sqrt(channelShare), theirs.rms, "RMS error");
        expectSixDigits(meanAbs(*ta, *rb) * channelShare, theirs.mean, "Mean error");
        expectSixDigits(ours.psnr - 10.0 * std::log10(channelShare), theirs.psnr, "Peak SNR");
        expectSixDigits(ours.maxAbs, theirs.max, "Max error");
        EXPECT_EQ(theirs.maxX, int(ours.maxAbsX));
        EXPECT_EQ(theirs.maxY, int(ours.maxAbsY));
    }
}
