// FLIP's viewing geometry and pooled statistics (see flip.h).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/image/flip.h"

namespace tp {
namespace {

// FLIP values are non-negative floats, whose bit patterns sort like the values: an LSD radix
// sort (3 passes of 11 bits) is ~10x faster than std::sort on a 1080p map.
void sortFlipValues(std::vector<float>& values) {
    for (float v : values)
        if (!(v >= 0.0f)) { // negative or NaN: not a FLIP map, take the general path
            std::sort(values.begin(), values.end());
            return;
        }
    std::vector<uint32_t> keys(values.size()), scratch(values.size());
    for (size_t i = 0; i < values.size(); ++i)
        keys[i] = std::bit_cast<uint32_t>(values[i]);
    for (int shift = 0; shift < 33; shift += 11) {
        std::vector<size_t> offsets(2049, 0);
        for (uint32_t k : keys)
            ++offsets[((k >> shift) & 2047u) + 1];
        for (size_t b = 1; b < offsets.size(); ++b)
            offsets[b] += offsets[b - 1];
        for (uint32_t k : keys)
            scratch[offsets[(k >> shift) & 2047u]++] = k;
        keys.swap(scratch);
    }
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = std::bit_cast<float>(keys[i]);
}

} // namespace

float flipPixelsPerDegree(float distanceMetres) {
    return distanceMetres * (kFlipMonitorWidthPixels / kFlipMonitorWidthMetres) *
           (std::numbers::pi_v<float> / 180.0f);
}

FlipStats poolFlip(const ImageR32& map) {
    FlipStats s;
    if (map.r.empty()) return s;
    std::vector<float> sorted = map.r;
    sortFlipValues(sorted);
    double total = 0.0;
    for (float v : sorted)
        total += v;
    s.mean = total / double(sorted.size());
    s.min = sorted.front();
    s.max = sorted.back();
    // Weighted percentile p: the smallest value at which the running sum of the sorted values
    // reaches p of their total.
    auto weighted = [&](double p) {
        if (total <= 0.0) return 0.0;
        const double target = p * total;
        double running = 0.0;
        for (float v : sorted) {
            running += v;
            if (running >= target) return double(v);
        }
        return double(sorted.back());
    };
    s.weightedQ1 = weighted(0.25);
    s.weightedMedian = weighted(0.5);
    s.weightedQ3 = weighted(0.75);
    return s;
}

} // namespace tp
