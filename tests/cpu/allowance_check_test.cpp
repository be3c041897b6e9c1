// errorBeyondAllowance (core/renderer/error_model.h): what each pixel's allowance explains is
// taken out on its side of the reference, and +Inf allowances are counted and left out.
#include <limits>

#include <gtest/gtest.h>

#include "core/renderer/error_model.h"
#include "include/tonemap.h"

namespace tp {
namespace {

constexpr float kEv = 0.0f;

// A one-row image whose pixel i is grey v[i].
ImageRGBA grey(std::initializer_list<float> v) {
    ImageRGBA img(uint32_t(v.size()), 1);
    size_t i = 0;
    for (float x : v) {
        for (int c = 0; c < 3; ++c)
            img.rgba[i * 4 + c] = x;
        img.rgba[i * 4 + 3] = 1.0f;
        ++i;
    }
    return img;
}

ErrorBound withAllowance(std::initializer_list<float> a) {
    ErrorBound b;
    b.perPixel.name = "test";
    b.perPixel.radiance = {uint32_t(a.size()), 1, a};
    return b;
}

double t(float x) {
    return gpu::tonemap(gpu::vec3(x), kEv).x;
}

TEST(AllowanceCheck, WithoutAllowanceItIsThePlainTonemappedMax) {
    const AllowanceCheck r =
        errorBeyondAllowance(ErrorBound{}, grey({0.5f, 1.3f}), grey({0.5f, 1.0f}), kEv);
    EXPECT_DOUBLE_EQ(r.worstBeyond, t(1.3f) - t(1.0f));
    EXPECT_EQ(r.widenedPixels, 0u);
    EXPECT_EQ(r.unboundedPixels, 0u);
}

TEST(AllowanceCheck, TheAllowanceExplainsItsOwnSizeOnEitherSide) {
    const ImageRGBA ref = grey({1.0f, 1.0f, 0.05f});
    const ErrorBound b = withAllowance({0.25f, 0.25f, 0.25f});
    // above by the allowance, below by it, and below down to black (clamped at 0)
    EXPECT_LE(errorBeyondAllowance(b, grey({1.25f, 0.75f, 0.0f}), ref, kEv).worstBeyond, 0.0);
    // twice the allowance above: only the second half counts
    const AllowanceCheck over = errorBeyondAllowance(b, grey({1.5f, 1.0f, 0.05f}), ref, kEv);
    EXPECT_NEAR(over.worstBeyond, t(1.5f) - t(1.25f), 1e-7);
    EXPECT_GT(over.worstBeyond, 0.0);
    EXPECT_EQ(over.widenedPixels, 3u);
}

TEST(AllowanceCheck, InfiniteAllowancesAreCountedAndLeftOut) {
    const float inf = std::numeric_limits<float>::infinity();
    const AllowanceCheck r = errorBeyondAllowance(withAllowance({inf, 0.0f}), grey({100.0f, 1.0f}),
                                                  grey({1.0f, 1.0f}), kEv);
    EXPECT_EQ(r.unboundedPixels, 1u);
    EXPECT_EQ(r.widenedPixels, 0u);
    EXPECT_EQ(r.worstBeyond, 0.0);
}

} // namespace
} // namespace tp
