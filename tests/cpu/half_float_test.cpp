// halfToFloat (core/gpu/readback.h), the viewer's per-view conversion of an RGBA16F image: every
// one of the 65,536 half values converts to what glm's software conversion gives (bit for bit;
// a NaN to a NaN), at every offset of the eight-wide loop and its tail.
#include <cmath>
#include <cstring>
#include <vector>

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include "core/gpu/readback.h"

namespace tp {
namespace {

TEST(HalfToFloat, EveryHalfConvertsAsGlmDoes) {
    std::vector<uint16_t> halves(65536 + 5); // + 5: a tail after the last full group of 8
    for (size_t i = 0; i < halves.size(); ++i)
        halves[i] = uint16_t(i);
    std::vector<float> out(halves.size());
    halfToFloat(halves.data(), out.data(), halves.size());
    size_t wrong = 0;
    for (size_t i = 0; i < halves.size(); ++i) {
        const float want = glm::unpackHalf1x16(halves[i]);
        const bool same = std::isnan(want) ? std::isnan(out[i])
                                           : std::memcmp(&want, &out[i], sizeof(float)) == 0;
        if (!same && wrong++ < 5) ADD_FAILURE() << "half 0x" << std::hex << halves[i];
    }
    EXPECT_EQ(wrong, 0u);
}

} // namespace
} // namespace tp
