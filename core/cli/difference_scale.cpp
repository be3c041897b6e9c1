#include "core/cli/difference_scale.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace tp {

float differencePercentile99(const ImageRGBA& signedDiff) {
    std::vector<float> values;
    values.reserve(signedDiff.pixelCount());
    for (size_t i = 0; i < signedDiff.pixelCount(); ++i) {
        const float* px = &signedDiff.rgba[i * 4];
        float m = std::max({std::abs(px[0]), std::abs(px[1]), std::abs(px[2])});
        if (std::isfinite(m)) values.push_back(m);
    }
    if (values.empty()) return 0.0f;
    size_t k = std::min(values.size() - 1, size_t(std::ceil(0.99 * double(values.size()))) - 1);
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

} // namespace tp
