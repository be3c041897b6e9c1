#pragma once
// A linear RGBA float image on the CPU: what readback produces and what metrics, EXR/PNG
// writers and difference images consume. Row 0 is the top row.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tp {

struct ImageRGBA {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgba; // width*height*4

    ImageRGBA() = default;
    ImageRGBA(uint32_t w, uint32_t h) : width(w), height(h), rgba(size_t(w) * h * 4, 0.0f) {}
    float* at(uint32_t x, uint32_t y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const float* at(uint32_t x, uint32_t y) const { return &rgba[(size_t(y) * width + x) * 4]; }
    size_t pixelCount() const { return size_t(width) * height; }
};

// A single-channel float image (depth, masks, heat-map inputs).
struct ImageR32 {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> r;
};

} // namespace tp
