// The viewer's GPU composite (viewer/gpu_composite.h) against composite.h's CPU rules, on the
// default device with validation on: the same bytes for the split view and the heat map (a
// tonemapped value may land one step away: the GPU's pow and exp2 are not the CPU's), the
// same 99th percentile to the bit, and auto exposure within float rounding.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "core/gpu/context.h"
#include "core/image/difference.h"
#include "core/image/tonemap.h"
#include "viewer/composite.h"
#include "viewer/gpu_composite.h"

namespace tp::view {
namespace gpu_composite_test {

constexpr uint32_t kCompW = 67, kCompH = 41; // not a multiple of the 16 x 16 workgroup

// Values over the tonemap's range (dark to far past white), a few NaNs and infinities, and a
// copy with some pixels moved: the heat map has a spread to rank.
ImageRGBA randomImage(uint32_t seed, bool specials, uint32_t w = kCompW, uint32_t h = kCompH) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> exponent(-8.0f, 4.0f);
    ImageRGBA img(w, h);
    for (size_t i = 0; i < img.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c)
            img.rgba[i * 4 + c] = std::exp2(exponent(rng));
        img.rgba[i * 4 + 3] = 1.0f;
    }
    if (specials) {
        img.rgba[5 * 4] = std::numeric_limits<float>::quiet_NaN();
        img.rgba[77 * 4 + 1] = std::numeric_limits<float>::infinity();
        img.rgba[300 * 4 + 2] = -1.0f;
        img.rgba[400 * 4 + 1] = std::numeric_limits<float>::quiet_NaN(); // passed over by std::max
    }
    return img;
}

struct Fixture {
    std::unique_ptr<GpuContext> ctx;
    std::unique_ptr<GpuComposite> gpu;
    Fixture() {
        ContextOptions o;
        o.validate = true;
        Result<std::unique_ptr<GpuContext>> c = GpuContext::create(o);
        if (!c) return;
        ctx = std::move(*c);
        gpu = std::make_unique<GpuComposite>(*ctx);
    }
    ~Fixture() {
        if (!ctx) return;
        gpu.reset();
        EXPECT_TRUE(ctx->validationMessages().empty()) << ctx->validationMessages().front();
    }
};

// The largest per-channel difference between the CPU's bytes and the GPU's, and how many
// channels differ at all.
std::pair<int, size_t> compareBytes(const Composite& cpu, const std::vector<uint8_t>& gpu) {
    EXPECT_EQ(cpu.rgba.size(), gpu.size());
    int worst = 0;
    size_t differing = 0;
    for (size_t i = 0; i < std::min(cpu.rgba.size(), gpu.size()); ++i) {
        const int d = std::abs(int(cpu.rgba[i]) - int(gpu[i]));
        worst = std::max(worst, d);
        differing += d != 0;
    }
    return {worst, differing};
}

TEST(GpuComposite, SplitMatchesTheCpuRulesWithinOneStep) {
    Fixture f;
    ASSERT_TRUE(f.ctx);
    const ImageRGBA a = randomImage(1, true), b = randomImage(2, false);
    for (bool flip : {false, true}) {
        CompositeInput in{&a, &b, nullptr, DisplayMode::Split, 0.37f, flip, 0.5f};
        const Composite cpu = compose(in, kCompW, kCompH);
        const Composite gpu = f.gpu->compose(in, {nullptr, &a, 1}, {nullptr, &b, 2}, kCompW, kCompH, false);
        EXPECT_EQ(gpu.width, cpu.width);
        EXPECT_EQ(gpu.height, cpu.height);
        const auto [worst, differing] = compareBytes(cpu, f.gpu->readBytes(gpu));
        EXPECT_LE(worst, 1) << "flip " << flip;
        EXPECT_LT(differing, cpu.rgba.size() / 100) << "flip " << flip;
    }
    // A side of another size (the reference of the previous resolution): nearest-scaled, as
    // composite.cpp's blit.
    const ImageRGBA small = randomImage(6, false, 31, 17);
    CompositeInput scaled{&a, &small, nullptr, DisplayMode::Split, 0.5f, false, 0.0f};
    const Composite cpuScaled = compose(scaled, kCompW, kCompH);
    const Composite gpuScaled =
        f.gpu->compose(scaled, {nullptr, &a, 1}, {nullptr, &small, 3}, kCompW, kCompH, false);
    EXPECT_LE(compareBytes(cpuScaled, f.gpu->readBytes(gpuScaled)).first, 1) << "scaled B";
    // One side missing: black there, and the note says so.
    CompositeInput in{&a, nullptr, nullptr, DisplayMode::Split, 0.5f, false, 0.0f};
    const Composite gpu = f.gpu->compose(in, {nullptr, &a, 1}, {}, kCompW, kCompH, false);
    EXPECT_EQ(gpu.note, "rendering...");
    const std::vector<uint8_t> bytes = f.gpu->readBytes(gpu);
    EXPECT_EQ(bytes[(10 * kCompW + kCompW - 1) * 4], 0);
    EXPECT_EQ(bytes[(10 * kCompW + kCompW - 1) * 4 + 3], 255);
}

TEST(GpuComposite, HeatMapAndItsScaleAreTheCpusToTheBit) {
    Fixture f;
    ASSERT_TRUE(f.ctx);
    const ImageRGBA a = randomImage(3, true), b = randomImage(4, false);
    CompositeInput in{&a, &b, nullptr, DisplayMode::Difference, 0.5f, false, 0.0f};
    const Composite cpu = compose(in, kCompW, kCompH);
    const Composite gpu = f.gpu->compose(in, {nullptr, &a, 1}, {nullptr, &b, 2}, kCompW, kCompH, false);
    EXPECT_EQ(gpu.diffScale, cpu.diffScale); // the radix select finds the CPU's nth_element
    EXPECT_EQ(gpu.height, kCompH + kLegendHeight);
    const auto [worst, differing] = compareBytes(cpu, f.gpu->readBytes(gpu));
    EXPECT_LE(worst, 1); // the ramp's interpolation may contract to an FMA on the GPU
    EXPECT_LT(differing, cpu.rgba.size() / 100);
}

TEST(GpuComposite, AutoExposureIsTheCpusWithinFloatRounding) {
    Fixture f;
    ASSERT_TRUE(f.ctx);
    const ImageRGBA a = randomImage(5, true);
    const float cpu = autoExposureEv(a);
    const float gpu = f.gpu->autoExposureEv({nullptr, &a, 1});
    EXPECT_NEAR(gpu, cpu, 1e-4f);
    EXPECT_NE(cpu, 0.0f);
}

} // namespace gpu_composite_test
} // namespace tp::view
