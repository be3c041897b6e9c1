#pragma once
// FLIP's colour spaces (Andersson et al. 2020, section 3): linear sRGB <-> CIE XYZ (D65),
// XYZ <-> YyCxCz (the linearised opponent space the contrast-sensitivity filters act in),
// XYZ -> CIE L*a*b*, the Hunt adjustment and the HyAB distance. Inline so the per-pixel loops
// of flip_ldr.cpp can vectorise; everything is float, as in the reference implementation.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace tp::flip {

struct Vec3 {
    float x, y, z;
};

// The sRGB -> XYZ matrix as exact ratios of the primaries' chromaticities (D65): the reference
// white below is its row sums, i.e. XYZ of linear RGB (1, 1, 1).
inline constexpr double kRgbToXyz[9] = {
    10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0,
    2613072.0 / 12288897.0,  8788810.0 / 12288897.0, 887015.0 / 12288897.0,
    1425312.0 / 73733382.0,  8788810.0 / 73733382.0, 70074185.0 / 73733382.0,
};

// Matrices in float, derived at compile time from kRgbToXyz (the inverse in double, then
// rounded), so the per-pixel code sees constants.
struct ColorConstants {
    float rgbToXyz[9];
    float xyzToRgb[9];
    Vec3 white;    // XYZ of RGB (1,1,1)
    Vec3 invWhite; // 1 / white
};

constexpr ColorConstants makeColorConstants() {
    const double* m = kRgbToXyz;
    const double c[9] = {
        m[4] * m[8] - m[5] * m[7], m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
        m[5] * m[6] - m[3] * m[8], m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
        m[3] * m[7] - m[4] * m[6], m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3],
    };
    const double det = m[0] * c[0] + m[1] * c[3] + m[2] * c[6];
    ColorConstants k{};
    for (int i = 0; i < 9; ++i) {
        k.rgbToXyz[i] = float(m[i]);
        k.xyzToRgb[i] = float(c[i] / det);
    }
    const double wx = m[0] + m[1] + m[2], wy = m[3] + m[4] + m[5], wz = m[6] + m[7] + m[8];
    k.white = {float(wx), float(wy), float(wz)};
    k.invWhite = {float(1.0 / wx), float(1.0 / wy), float(1.0 / wz)};
    return k;
}
inline constexpr ColorConstants kColor = makeColorConstants();

inline Vec3 mul3(const float* m, Vec3 v) {
    return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
            m[6] * v.x + m[7] * v.y + m[8] * v.z};
}

inline Vec3 linearRgbToXyz(Vec3 rgb) {
    return mul3(kColor.rgbToXyz, rgb);
}
inline Vec3 xyzToLinearRgb(Vec3 xyz) {
    return mul3(kColor.xyzToRgb, xyz);
}

// YyCxCz: Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn); like L*a*b*
// without the cube root, so it is linear and a blur in it is a blur of light.
inline Vec3 xyzToYcxcz(Vec3 xyz) {
    constexpr Vec3 iw = kColor.invWhite;
    const float x = xyz.x * iw.x, y = xyz.y * iw.y, z = xyz.z * iw.z;
    return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

inline Vec3 ycxczToXyz(Vec3 c) {
    constexpr Vec3 w = kColor.white;
    const float y = (c.x + 16.0f) / 116.0f;
    const float x = c.y / 500.0f + y;
    const float z = y - c.z / 200.0f;
    return {x * w.x, y * w.y, z * w.z};
}

// Branch-free cbrt, log2, exp2 and pow (to about 1e-7 relative) so the per-pixel loops
// vectorise; libm's scalar calls were a third of the run time. Inputs are what FLIP feeds
// them: cbrt of values in [0, 1.1], pow of a non-negative base.
inline float fastCbrt(float x) {
    x = std::max(x, 1e-30f);
    // Exponent / 3 on the bit pattern gives a ~5% guess; the division by 3 goes through float
    // because vector units have no integer divide.
    const float third = float(std::bit_cast<int32_t>(x)) * (1.0f / 3.0f);
    float y = std::bit_cast<float>(int32_t(third) + 0x2a5137a0);
    // Two Halley steps (cubic convergence: 5% -> 1e-4 -> 1e-12), written out: a loop here
    // keeps GCC from vectorising the callers.
    float y3 = y * y * y;
    y = y * (y3 + 2.0f * x) / (2.0f * y3 + x);
    y3 = y * y * y;
    return y * (y3 + 2.0f * x) / (2.0f * y3 + x);
}

// log2 of x >= FLT_MIN: exponent plus atanh series of the mantissa in [sqrt(1/2), sqrt(2)).
inline float fastLog2(float x) {
    const uint32_t bits = std::bit_cast<uint32_t>(x);
    int e = int(bits >> 23) - 127;
    float m = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u); // [1, 2)
    const bool high = m > 1.41421356f;
    m = high ? 0.5f * m : m;
    e = high ? e + 1 : e;
    const float t = (m - 1.0f) / (m + 1.0f), t2 = t * t; // |t| <= 0.172
    const float series =
        1.0f + t2 * (1.0f / 3 + t2 * (1.0f / 5 + t2 * (1.0f / 7 + t2 * (1.0f / 9))));
    return float(e) + 2.0f * t * series * 1.44269504f;
}

// 2^v, v clamped to [-126, 126]: integer part into the exponent, Taylor series for the rest.
inline float fastExp2(float v) {
    v = std::min(std::max(v, -126.0f), 126.0f);
    const int n = int(v + 127.5f) - 127;           // round to nearest: v + 127.5 > 0
    const float z = (v - float(n)) * 0.693147181f; // |z| <= 0.347
    const float p =
        1.0f +
        z * (1.0f +
             z * (1.0f / 2 +
                  z * (1.0f / 6 +
                       z * (1.0f / 24 + z * (1.0f / 120 + z * (1.0f / 720 + z * (1.0f / 5040)))))));
    return p * std::bit_cast<float>(uint32_t(n + 127) << 23);
}

// x^y for x >= 0, with 0^0 = 1 and 0^y = 0 for y > 0, as std::pow.
inline float fastPow(float x, float y) {
    const float v = fastExp2(y * fastLog2(std::max(x, 1.17549435e-38f)));
    return x > 0.0f ? v : (y == 0.0f ? 1.0f : 0.0f);
}

// sRGB transfer function (IEC 61966-2-1) decode: display value in [0,1] -> linear.
inline float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : fastPow((c + 0.055f) / 1.055f, 2.4f);
}

// CIE L*a*b* relative to the same white.
inline float labF(float t) {
    constexpr float delta = 6.0f / 29.0f;
    constexpr float delta3 = delta * delta * delta;
    return t > delta3 ? fastCbrt(t) : t / (3.0f * delta * delta) + 4.0f / 29.0f;
}

inline Vec3 xyzToLab(Vec3 xyz) {
    constexpr Vec3 iw = kColor.invWhite;
    const float fx = labF(xyz.x * iw.x), fy = labF(xyz.y * iw.y), fz = labF(xyz.z * iw.z);
    return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// Hunt effect: chroma is less visible at low luminance, so a* and b* scale with L*/100.
inline Vec3 huntAdjust(Vec3 lab) {
    return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z};
}

// HyAB (Abasi et al. 2020): city-block in lightness plus Euclidean in the chroma plane, which
// follows large colour differences better than Euclidean L*a*b*.
inline float hyab(Vec3 a, Vec3 b) {
    const float da = a.y - b.y, db = a.z - b.z;
    return std::abs(a.x - b.x) + std::sqrt(da * da + db * db);
}

// Linear RGB clamped to [0,1] -> Hunt-adjusted L*a*b*: what the colour pipeline compares.
inline Vec3 linearRgbToHuntLab(Vec3 rgb) {
    rgb = {std::clamp(rgb.x, 0.0f, 1.0f), std::clamp(rgb.y, 0.0f, 1.0f),
           std::clamp(rgb.z, 0.0f, 1.0f)};
    return huntAdjust(xyzToLab(linearRgbToXyz(rgb)));
}

} // namespace tp::flip
