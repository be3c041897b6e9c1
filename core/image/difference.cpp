// Difference images. The heat map carries its own legend (gradient bar, "0" and the scale
// maximum drawn with a built-in 5x7 font) so a PNG read on its own still says what a colour
// means.
#include "core/image/difference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace tp {
namespace {

using Rgb = std::array<float, 3>;

// Matplotlib's 'inferno' sampled at 10 evenly spaced points (sRGB, display space):
// perceptually uniform, monotonic in lightness and readable in greyscale.
constexpr std::array<Rgb, 10> kInferno = {{
    {0x00 / 255.f, 0x00 / 255.f, 0x04 / 255.f},
    {0x1b / 255.f, 0x0c / 255.f, 0x42 / 255.f},
    {0x4b / 255.f, 0x0c / 255.f, 0x6b / 255.f},
    {0x78 / 255.f, 0x1c / 255.f, 0x6d / 255.f},
    {0xa5 / 255.f, 0x2c / 255.f, 0x60 / 255.f},
    {0xcf / 255.f, 0x44 / 255.f, 0x46 / 255.f},
    {0xed / 255.f, 0x69 / 255.f, 0x25 / 255.f},
    {0xfb / 255.f, 0x9a / 255.f, 0x06 / 255.f},
    {0xf7 / 255.f, 0xd0 / 255.f, 0x3c / 255.f},
    {0xfc / 255.f, 0xff / 255.f, 0xa4 / 255.f},
}};
// Matplotlib's 'magma' sampled at 10 evenly spaced points (sRGB): the colour map FLIP's
// error maps use, so ours read like the ones in the FLIP papers.
constexpr std::array<Rgb, 10> kMagma = {{
    {0x00 / 255.f, 0x00 / 255.f, 0x04 / 255.f},
    {0x18 / 255.f, 0x0f / 255.f, 0x3d / 255.f},
    {0x44 / 255.f, 0x0f / 255.f, 0x76 / 255.f},
    {0x72 / 255.f, 0x1f / 255.f, 0x81 / 255.f},
    {0x9e / 255.f, 0x2f / 255.f, 0x7f / 255.f},
    {0xcd / 255.f, 0x40 / 255.f, 0x71 / 255.f},
    {0xf1 / 255.f, 0x60 / 255.f, 0x5d / 255.f},
    {0xfd / 255.f, 0x96 / 255.f, 0x68 / 255.f},
    {0xfe / 255.f, 0xca / 255.f, 0x8d / 255.f},
    {0xfc / 255.f, 0xfd / 255.f, 0xbf / 255.f},
}};
using Ramp = std::array<Rgb, 10>;
constexpr Rgb kMagenta = {1.0f, 0.0f, 1.0f}; // NaN/Inf: not on the ramp, cannot be misread
constexpr Rgb kLegendBackground = {0.2f, 0.2f, 0.2f};
constexpr Rgb kLegendText = {1.0f, 1.0f, 1.0f};

// 5x7 glyphs, one byte per row, bit 4 = leftmost column.
struct Glyph {
    char c;
    std::array<uint8_t, 7> rows;
};
constexpr std::array<Glyph, 14> kFont = {{
    {'0', {0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e}},
    {'1', {0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e}},
    {'2', {0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f}},
    {'3', {0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e}},
    {'4', {0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02}},
    {'5', {0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e}},
    {'6', {0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e}},
    {'7', {0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e}},
    {'9', {0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c}},
    {'e', {0x00, 0x00, 0x0e, 0x11, 0x1f, 0x10, 0x0e}},
    {'-', {0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00}},
    {'+', {0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00}},
}};
constexpr int kGlyphW = 5, kGlyphH = 7, kGlyphAdvance = 6;

Rgb ramp(float t, const Ramp& colours = kInferno) {
    t = std::clamp(t, 0.0f, 1.0f) * float(colours.size() - 1);
    size_t i = std::min(size_t(t), colours.size() - 2);
    float f = t - float(i);
    Rgb out;
    for (int c = 0; c < 3; ++c)
        out[c] = colours[i][c] + f * (colours[i + 1][c] - colours[i][c]);
    return out;
}

void setPixel(ImageRGBA& image, int x, int y, const Rgb& colour) {
    if (x < 0 || y < 0 || x >= int(image.width) || y >= int(image.height)) return;
    float* px = image.at(uint32_t(x), uint32_t(y));
    px[0] = colour[0];
    px[1] = colour[1];
    px[2] = colour[2];
    px[3] = 1.0f;
}

const Glyph* findGlyph(char c) {
    for (const Glyph& g : kFont)
        if (g.c == c) return &g;
    return nullptr;
}

int textWidth(const std::string& text, int scale) {
    return text.empty() ? 0 : (int(text.size()) * kGlyphAdvance - 1) * scale;
}

// Draws at (x, y) = top-left, each font pixel a scale x scale block; clipped to the image.
void drawText(ImageRGBA& image, const std::string& text, int x, int y, int scale) {
    for (size_t i = 0; i < text.size(); ++i) {
        const Glyph* g = findGlyph(text[i]);
        if (!g) continue;
        int gx = x + int(i) * kGlyphAdvance * scale;
        for (int row = 0; row < kGlyphH * scale; ++row)
            for (int col = 0; col < kGlyphW * scale; ++col)
                if (g->rows[row / scale] & (0x10 >> (col / scale)))
                    setPixel(image, gx + col, y + row, kLegendText);
    }
}

// The shortest label that round-trips to a few digits: "0.05", "1e+03", "2.5e-05".
std::string formatScale(float value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", double(value));
    return buffer;
}

// Legend rows [top, top + height): a bar from 0 to scaleMax with the two labels under it.
// Too short for text (under 14 px at scale 1) leaves only the bar.
void drawLegend(ImageRGBA& image, uint32_t top, uint32_t height, float scaleMax,
                const Ramp& colours = kInferno) {
    for (uint32_t y = top; y < top + height; ++y)
        for (uint32_t x = 0; x < image.width; ++x)
            setPixel(image, int(x), int(y), kLegendBackground);

    const int scale = std::max(1, int(height) / 24);
    const int margin = 2 * scale;
    const bool withText = int(height) >= kGlyphH * scale + 3 * margin + scale;
    const int barTop = int(top) + (withText ? margin : 0);
    const int barBottom = withText ? int(top + height) - kGlyphH * scale - 2 * margin
                                   : int(top + height); // exclusive
    const int barLeft = std::min(margin, int(image.width) / 4);
    const int barRight = int(image.width) - 1 - barLeft; // inclusive
    const float span = float(std::max(1, barRight - barLeft));
    for (int x = barLeft; x <= barRight; ++x) {
        Rgb colour = ramp(float(x - barLeft) / span, colours);
        for (int y = barTop; y < barBottom; ++y)
            setPixel(image, x, y, colour);
    }
    if (!withText) return;

    const int textTop = int(top + height) - kGlyphH * scale - margin;
    drawText(image, "0", barLeft, textTop, scale);
    std::string maxLabel = formatScale(scaleMax);
    drawText(image, maxLabel, barRight + 1 - textWidth(maxLabel, scale), textTop, scale);
}

} // namespace

ImageRGBA flipErrorMap(const ImageR32& flipValues, uint32_t legendHeight) {
    ImageRGBA out(flipValues.width, flipValues.height + legendHeight);
    if (flipValues.r.size() != size_t(flipValues.width) * flipValues.height) return {};
    for (uint32_t y = 0; y < flipValues.height; ++y)
        for (uint32_t x = 0; x < flipValues.width; ++x) {
            const float v = flipValues.r[size_t(y) * flipValues.width + x];
            setPixel(out, int(x), int(y), std::isfinite(v) ? ramp(v, kMagma) : kMagenta);
        }
    if (legendHeight > 0 && out.width > 0)
        drawLegend(out, flipValues.height, legendHeight, 1.0f, kMagma);
    return out;
}

ImageRGBA signedDifference(const ImageRGBA& test, const ImageRGBA& reference) {
    if (test.width != reference.width || test.height != reference.height) return {};
    ImageRGBA diff(test.width, test.height);
    for (size_t i = 0; i < diff.pixelCount(); ++i) {
        for (int c = 0; c < 3; ++c)
            diff.rgba[i * 4 + c] = test.rgba[i * 4 + c] - reference.rgba[i * 4 + c];
        diff.rgba[i * 4 + 3] = 1.0f;
    }
    return diff;
}

ImageRGBA heatMap(const ImageRGBA& signedDiff, float scaleMax, uint32_t legendHeight) {
    ImageRGBA out(signedDiff.width, signedDiff.height + legendHeight);
    // A non-positive or non-finite scale would divide by zero: any error then saturates.
    const bool usableScale = std::isfinite(scaleMax) && scaleMax > 0.0f;
    for (uint32_t y = 0; y < signedDiff.height; ++y) {
        for (uint32_t x = 0; x < signedDiff.width; ++x) {
            const float* d = signedDiff.at(x, y);
            if (!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2])) {
                setPixel(out, int(x), int(y), kMagenta);
                continue;
            }
            float v = std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
            float t = usableScale ? v / scaleMax : (v > 0.0f ? 1.0f : 0.0f);
            setPixel(out, int(x), int(y), ramp(t));
        }
    }
    if (legendHeight > 0 && out.width > 0)
        drawLegend(out, signedDiff.height, legendHeight, scaleMax);
    return out;
}

std::vector<std::array<float, 3>> heatRamp() {
    return std::vector<std::array<float, 3>>(kInferno.begin(), kInferno.end());
}

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
