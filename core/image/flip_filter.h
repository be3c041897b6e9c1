#pragma once
// FLIP's filters, all separable: the contrast-sensitivity (CSF) filters of the colour pipeline
// and the edge and point detectors of the feature pipeline (Andersson et al. 2020, sections
// 3.1 and 3.3), plus the row/column convolutions (edges clamped) and a row-parallel loop.
#include <cstdint>
#include <functional>
#include <vector>

// The hot loops are compiled three times, for AVX-512 (x86-64-v4), AVX2 (x86-64-v3) and the
// baseline, and the loader picks one at start-up (GCC function multiversioning): wide vectors
// on any recent x86 without making the binary require them (AVX-512 saved ~10% over AVX2 on
// the development machine's EPYC).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define TP_FLIP_SIMD __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define TP_FLIP_SIMD
#endif

namespace tp::flip {

// A 1D kernel of 2 * radius + 1 taps, centre at index radius.
struct Kernel {
    int radius = 0;
    std::vector<float> taps;
};

// The CSF of one opponent channel is a sum of Gaussians in visual angle,
//   S(x) = sum_i a_i sqrt(pi / b_i) exp(-pi^2 x^2 / b_i),
// applied in 2D with x the distance from the centre in degrees and normalised to sum 1.
// Each Gaussian is separable, so the 2D kernel is sum_i weight_i * g_i(x) g_i(y) with g_i
// normalised to sum 1 and weight_i its share of the 2D sum: exactly the 2D filter.
struct CsfFilter {
    std::vector<Kernel> gaussians; // 1D, each sums to 1
    std::vector<float> weights;    // sum to 1
};

struct CsfFilters {
    CsfFilter achromatic, redGreen, blueYellow;
};

// Radius (in pixels) shared by the three channels: 3 standard deviations of the widest
// Gaussian, ceil(3 sqrt(b_max / (2 pi^2)) ppd).
CsfFilters makeCsfFilters(float ppd);

// Feature detectors: a Gaussian of standard deviation 0.5 * 0.082 degrees (half the
// peak-to-trough width of the eye's edge detector) and its first and second derivatives,
// radius ceil(3 sigma). The 2D edge filter in x is firstDerivative(x) * gaussian(y), the
// point filter secondDerivative(x) * gaussian(y) (and transposed for y). Positive taps of a
// derivative sum to 1 and negative ones to -1 (so the 2D filters' do too); gaussian sums to 1.
struct FeatureFilters {
    Kernel gaussian, firstDerivative, secondDerivative;
};
FeatureFilters makeFeatureFilters(float ppd);

// out[x] = sum_k taps[k] * in[clamp(x + k - radius)] for each kernel, one row of `width`.
// `padded` is scratch. Kernels marked symmetric/antisymmetric take half the multiplies.
void convolveRow(const float* in, int width, const Kernel* const* kernels, float* const* outs,
                 int count, std::vector<float>& padded);

// out[x] = sum_k taps[k] * rows[clamp(y + k - radius)][x] for x in [0, count): the column pass
// for output row y of an image of `height` rows, `stride` floats apart, starting at `plane`
// (offset it to filter a strip of columns). Accumulates `scale` times the result into out
// when accumulate is set, else writes it.
void convolveColumn(const float* plane, int stride, int count, int height, int y,
                    const Kernel& kernel, float* out, float scale = 1.0f, bool accumulate = false);

// Runs fn(begin, end) on disjoint row ranges covering [0, rows), on the machine's cores.
void parallelRows(int rows, const std::function<void(int, int)>& fn);

} // namespace tp::flip
