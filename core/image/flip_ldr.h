#pragma once
// LDR-FLIP's per-pixel core on planar linear RGB, shared by ldrFlip and hdrFlip (which calls
// it once per exposure). See flip.h for the public interface.
#include <cstddef>
#include <vector>

namespace tp::flip {

struct LinearPlanes {
    int width = 0, height = 0;
    std::vector<float> r, g, b; // linear RGB in [0, 1], row-major, row 0 on top

    LinearPlanes() = default;
    LinearPlanes(int w, int h)
        : width(w), height(h), r(size_t(w) * h), g(size_t(w) * h), b(size_t(w) * h) {}
};

// Scratch planes of flipLinear, kept between calls (HDR-FLIP calls it once per exposure).
struct FlipWorkspace {
    std::vector<float> planes[2][7]; // row-filtered planes of reference and test
};

// LDR-FLIP of test against reference, per pixel, kept in out (width * height floats) where it
// is larger than what out holds: start from zeros for one evaluation; HDR-FLIP's maximum over
// exposures is repeated calls on the same out.
void flipLinear(const LinearPlanes& reference, const LinearPlanes& test, float ppd, float* out,
                FlipWorkspace& workspace);

} // namespace tp::flip
