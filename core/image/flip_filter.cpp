// FLIP's separable filters (see flip_filter.h). Constants: Table 1 of Andersson et al. 2020
// (CSF Gaussians per opponent channel) and section 3.3 (feature width 0.082 degrees).
#include "core/image/flip_filter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include "core/util/math.h"

namespace tp::flip {
namespace {

struct Gaussian {
    float a, b; // amplitude and scale (degrees^2) of a sqrt(pi/b) exp(-pi^2 x^2 / b)
};
// Achromatic and red-green are one Gaussian each; blue-yellow is two.
constexpr Gaussian kAchromatic[] = {{1.0f, 0.0047f}};
constexpr Gaussian kRedGreen[] = {{1.0f, 0.0053f}};
constexpr Gaussian kBlueYellow[] = {{34.1f, 0.04f}, {13.5f, 0.025f}};
constexpr float kMaxScale = 0.04f; // the largest b above: sets the common radius

constexpr float kFeatureWidthDegrees = 0.082f;

template <size_t N> CsfFilter makeCsf(const Gaussian (&gaussians)[N], int radius, float ppd) {
    CsfFilter filter;
    const float dx = 1.0f / ppd;
    double total = 0.0;
    std::vector<double> shares;
    for (const Gaussian& g : gaussians) {
        Kernel k{radius, std::vector<float>(size_t(2 * radius + 1))};
        double sum = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const float x = float(i) * dx;
            const float v = std::exp(-kPi * kPi * x * x / g.b);
            k.taps[size_t(i + radius)] = v;
            sum += v;
        }
        for (float& t : k.taps)
            t = float(t / sum);
        // Share of this Gaussian in the 2D kernel's sum: a sqrt(pi/b) (sum of 1D taps)^2.
        const double share = double(g.a) * std::sqrt(double(kPi) / double(g.b)) * sum * sum;
        shares.push_back(share);
        total += share;
        filter.gaussians.push_back(std::move(k));
    }
    for (double s : shares)
        filter.weights.push_back(float(s / total));
    return filter;
}

// Positive taps to sum 1, negative taps to sum -1.
void normalizeSigned(Kernel& k) {
    double positive = 0.0, negative = 0.0;
    for (float t : k.taps)
        (t > 0 ? positive : negative) += t;
    for (float& t : k.taps)
        t = t > 0 ? float(t / positive) : (t < 0 ? float(t / -negative) : 0.0f);
}

enum class Symmetry { None, Even, Odd };

Symmetry symmetryOf(const Kernel& k) {
    bool even = true, odd = k.taps[size_t(k.radius)] == 0.0f;
    for (int i = 1; i <= k.radius; ++i) {
        const float l = k.taps[size_t(k.radius - i)], r = k.taps[size_t(k.radius + i)];
        even = even && l == r;
        odd = odd && l == -r;
    }
    return even ? Symmetry::Even : odd ? Symmetry::Odd : Symmetry::None;
}

} // namespace

CsfFilters makeCsfFilters(float ppd) {
    const int radius = int(std::ceil(3.0f * std::sqrt(kMaxScale / (2.0f * kPi * kPi)) * ppd));
    return {makeCsf(kAchromatic, radius, ppd), makeCsf(kRedGreen, radius, ppd),
            makeCsf(kBlueYellow, radius, ppd)};
}

FeatureFilters makeFeatureFilters(float ppd) {
    const float sigma = 0.5f * kFeatureWidthDegrees * ppd;
    const int radius = int(std::ceil(3.0f * sigma));
    const size_t n = size_t(2 * radius + 1);
    FeatureFilters f{{radius, std::vector<float>(n)},
                     {radius, std::vector<float>(n)},
                     {radius, std::vector<float>(n)}};
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const float x = float(i);
        const float g = std::exp(-(x * x) / (2.0f * sigma * sigma));
        f.gaussian.taps[size_t(i + radius)] = g;
        f.firstDerivative.taps[size_t(i + radius)] = -x * g;
        f.secondDerivative.taps[size_t(i + radius)] = (x * x / (sigma * sigma) - 1.0f) * g;
        sum += g;
    }
    for (float& t : f.gaussian.taps)
        t = float(t / sum);
    normalizeSigned(f.firstDerivative);
    normalizeSigned(f.secondDerivative);
    return f;
}

TP_FLIP_SIMD void convolveRow(const float* in, int width, const Kernel* const* kernels,
                              float* const* outs, int count, std::vector<float>& padded) {
    int pad = 0;
    for (int i = 0; i < count; ++i)
        pad = std::max(pad, kernels[i]->radius);
    padded.resize(size_t(width + 2 * pad));
    for (int x = 0; x < width + 2 * pad; ++x)
        padded[size_t(x)] = in[std::clamp(x - pad, 0, width - 1)];
    const float* p = padded.data() + pad; // p[x] = in[clamp(x)] for x in [-pad, width + pad)
    for (int i = 0; i < count; ++i) {
        const Kernel& k = *kernels[i];
        float* out = outs[i];
        const float* t = k.taps.data() + k.radius; // t[j], j in [-radius, radius]
        const Symmetry s = symmetryOf(k);
        const float c = t[0];
        for (int x = 0; x < width; ++x)
            out[x] = c * p[x];
        if (s == Symmetry::None) {
            for (int j = -k.radius; j <= k.radius; ++j) {
                if (j == 0) continue;
                const float w = t[j];
                for (int x = 0; x < width; ++x)
                    out[x] += w * p[x + j];
            }
            continue;
        }
        const float sign = s == Symmetry::Even ? 1.0f : -1.0f;
        for (int j = 1; j <= k.radius; ++j) {
            const float w = t[j];
            const float* hi = p + j;
            const float* lo = p - j;
            if (sign > 0)
                for (int x = 0; x < width; ++x)
                    out[x] += w * (hi[x] + lo[x]);
            else
                for (int x = 0; x < width; ++x)
                    out[x] += w * (hi[x] - lo[x]);
        }
    }
}

TP_FLIP_SIMD void convolveColumn(const float* plane, int stride, int width, int height, int y,
                                 const Kernel& kernel, float* out, float scale, bool accumulate) {
    const float* t = kernel.taps.data() + kernel.radius;
    auto row = [&](int dy) {
        return plane + size_t(std::clamp(y + dy, 0, height - 1)) * size_t(stride);
    };
    const Symmetry s = symmetryOf(kernel);
    // Sum into a local row first, then scale: one rounding pattern for both modes.
    thread_local std::vector<float> acc;
    acc.resize(size_t(width));
    float* a = acc.data();
    const float* centre = row(0);
    for (int x = 0; x < width; ++x)
        a[x] = t[0] * centre[x];
    for (int j = 1; j <= kernel.radius; ++j) {
        const float* hi = row(j);
        const float* lo = row(-j);
        if (s == Symmetry::Even) {
            const float w = t[j];
            for (int x = 0; x < width; ++x)
                a[x] += w * (hi[x] + lo[x]);
        } else if (s == Symmetry::Odd) {
            const float w = t[j];
            for (int x = 0; x < width; ++x)
                a[x] += w * (hi[x] - lo[x]);
        } else {
            const float wh = t[j], wl = t[-j];
            for (int x = 0; x < width; ++x)
                a[x] += wh * hi[x] + wl * lo[x];
        }
    }
    if (accumulate)
        for (int x = 0; x < width; ++x)
            out[x] += scale * a[x];
    else if (scale != 1.0f)
        for (int x = 0; x < width; ++x)
            out[x] = scale * a[x];
    else
        std::copy(a, a + width, out);
}

void parallelRows(int rows, const std::function<void(int, int)>& fn) {
    const int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, 64);
    const int chunks = std::min(threads, std::max(1, rows / 16));
    if (chunks <= 1) {
        fn(0, rows);
        return;
    }
    std::vector<std::thread> pool;
    for (int i = 1; i < chunks; ++i)
        pool.emplace_back([&, i] { fn(rows * i / chunks, rows * (i + 1) / chunks); });
    fn(0, rows / chunks);
    for (std::thread& t : pool)
        t.join();
}

} // namespace tp::flip
