#include "viewer/composite.h"

#include <algorithm>
#include <cmath>

#include "core/image/difference.h"
#include "core/image/tonemap.h"

namespace tp::view {
namespace {

uint8_t toByte(float v) {
    if (!(v >= 0.0f)) return 0; // NaN too
    return uint8_t(std::lround(std::min(v, 1.0f) * 255.0f));
}

// Copies a display-space image into `out` at 1:1 (or nearest-scaled when sizes differ),
// columns [x0, x1) only.
void blit(const ImageRGBA& display, Composite& out, uint32_t height, uint32_t x0, uint32_t x1) {
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = x0; x < x1; ++x) {
            uint32_t sx = uint32_t(uint64_t(x) * display.width / out.width);
            uint32_t sy = uint32_t(uint64_t(y) * display.height / height);
            const float* p = display.at(sx, sy);
            uint8_t* o = &out.rgba[(size_t(y) * out.width + x) * 4];
            for (int c = 0; c < 3; ++c)
                o[c] = toByte(p[c]);
            o[3] = 255;
        }
}

void drawDivider(Composite& out, uint32_t column, uint32_t height) {
    for (uint32_t y = 0; y < height; ++y) {
        uint8_t* o = &out.rgba[(size_t(y) * out.width + column) * 4];
        o[0] = kDividerRgb[0], o[1] = kDividerRgb[1], o[2] = kDividerRgb[2], o[3] = 255;
    }
}

void composeSplit(const CompositeInput& in, Composite& out, uint32_t height) {
    const ImageRGBA* left = in.flip ? in.b : in.a;
    const ImageRGBA* right = in.flip ? in.a : in.b;
    // A's columns end where B's begin; at split 1 that is past the last column (A whole).
    const uint32_t boundary = std::min(
        out.width, uint32_t(std::floor(std::clamp(in.split, 0.0f, 1.0f) * float(out.width))));
    if (left) blit(tonemapToDisplay(*left, in.exposureEv), out, height, 0, boundary);
    if (right) blit(tonemapToDisplay(*right, in.exposureEv), out, height, boundary, out.width);
    if (!left || !right) out.note = "rendering...";
    // The divider only where both sides show something (at 0 or 1 the whole image is one side).
    if (in.split > 0.0f && in.split < 1.0f)
        drawDivider(out, dividerColumn(in.split, out.width), height);
}

void composeDifference(const CompositeInput& in, Composite& out) {
    if (!in.a || !in.b || in.a->width != in.b->width || in.a->height != in.b->height) {
        out.note = "the difference needs both images at one size";
        return;
    }
    ImageRGBA diff = signedDifference(*in.a, *in.b);
    // compare's rule (docs/report.md): the 99th percentile of max-channel |diff|, 1e-6 when 0.
    out.diffScale = differencePercentile99(diff);
    if (!(out.diffScale > 0.0f)) out.diffScale = 1e-6f;
    ImageRGBA map = heatMap(diff, out.diffScale, kLegendHeight);
    blit(map, out, out.height, 0, out.width);
}

} // namespace

uint32_t dividerColumn(float split, uint32_t width) {
    float s = std::clamp(split, 0.0f, 1.0f);
    return std::min(width - 1, uint32_t(std::floor(s * float(width))));
}

Composite compose(const CompositeInput& in, uint32_t width, uint32_t height) {
    Composite out;
    out.width = width;
    out.height = height + (in.mode == DisplayMode::Difference ? kLegendHeight : 0);
    out.rgba.assign(size_t(out.width) * out.height * 4, 0);
    for (size_t i = 3; i < out.rgba.size(); i += 4)
        out.rgba[i] = 255;
    if (in.mode == DisplayMode::Split)
        composeSplit(in, out, height);
    else if (in.mode == DisplayMode::Difference)
        composeDifference(in, out);
    else if (in.overlay)
        blit(*in.overlay, out, height, 0, width);
    else
        out.note = "this pipeline has no such debug image (or it is being rendered)";
    return out;
}

} // namespace tp::view
