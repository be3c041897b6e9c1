// The blended fragment pool's bound (visbuffer/fragment_bound.h) against a brute-force count:
// every pixel centre a triangle contains, its edges included (more than any rasterizer's
// tie-breaking rule keeps), never exceeds the bound, over random triangles of every size and
// place (partly or wholly off screen, degenerate, sliver); and the bound is no loose upper
// limit: within 25 % of the count for triangles of 400 centres or more (the rest is the
// perimeter term).
#include <gtest/gtest.h>

#include <random>

#include "visbuffer/fragment_bound.h"

namespace tp {
namespace {

constexpr uint32_t kBoundWidth = 64, kBoundHeight = 48;

double edge(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

uint32_t centresInside(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    uint32_t n = 0;
    for (uint32_t y = 0; y < kBoundHeight; ++y)
        for (uint32_t x = 0; x < kBoundWidth; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            const double e0 = edge(a, b, p), e1 = edge(b, c, p), e2 = edge(c, a, p);
            const double eps = 1e-9;
            const bool inside = (e0 >= -eps && e1 >= -eps && e2 >= -eps) ||
                                (e0 <= eps && e1 <= eps && e2 <= eps);
            const bool degenerate = std::abs(edge(a, b, c)) == 0.0;
            n += inside && !degenerate ? 1 : 0;
        }
    return n;
}

TEST(VisbufferFragmentBound, NeverBelowTheCentresATriangleContains) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(-20.0f, 84.0f), small(-2.0f, 2.0f);
    for (int i = 0; i < 3000; ++i) {
        glm::vec2 a(pos(rng), pos(rng)), b, c;
        if (i % 3 == 0) { // small or sliver triangles around a
            b = a + glm::vec2(small(rng), small(rng));
            c = a + glm::vec2(small(rng), small(rng)) * (i % 2 ? 30.0f : 1.0f);
        } else {
            b = glm::vec2(pos(rng), pos(rng));
            c = glm::vec2(pos(rng), pos(rng));
        }
        const double bound = vis::triangleCentreBound(a, b, c, kBoundWidth, kBoundHeight);
        const uint32_t count = centresInside(a, b, c);
        ASSERT_GE(bound, double(count)) << i;
        if (count >= 400) {
            EXPECT_LE(bound, 1.25 * count + 40) << i; // the perimeter term
        }
    }
}

TEST(VisbufferFragmentBound, CountsTheScreenOnceForAFullScreenPair) {
    const glm::vec2 a(0, 0), b(kBoundWidth, 0), c(kBoundWidth, kBoundHeight), d(0, kBoundHeight);
    const double both = vis::triangleCentreBound(a, b, c, kBoundWidth, kBoundHeight) +
                        vis::triangleCentreBound(a, c, d, kBoundWidth, kBoundHeight);
    EXPECT_GE(both, double(kBoundWidth) * kBoundHeight);
    EXPECT_LE(both, double(kBoundWidth) * kBoundHeight * 1.1 + 2 * (kBoundWidth + kBoundHeight)); // the shared diagonal twice
    EXPECT_EQ(vis::triangleCentreBound({-10, -10}, {-5, -10}, {-5, -1}, kBoundWidth, kBoundHeight), 0.0);
}

} // namespace
} // namespace tp
