// LDR-FLIP (Andersson et al. 2020). Two pipelines per pixel, both images through each:
//   colour:  linear RGB -> YyCxCz -> CSF filters -> linear RGB clamped to [0,1] -> Hunt-adjusted
//            L*a*b* -> HyAB distance -> ^0.7 -> redistributed to [0,1] against the largest
//            distance (green vs blue), 95% of the range going to the lower 40% of distances;
//   feature: normalised achromatic Yy of the unfiltered images -> edge (1st derivative of a
//            Gaussian) and point (2nd derivative) magnitudes -> the larger of the two
//            differences / sqrt(2) -> ^0.5.
// FLIP = colour ^ (1 - feature): a feature difference pushes a colour difference towards 1.
//
// Memory: the row passes write 7 planes per image; the column pass and the per-pixel part
// run together per row, so filtered images are never stored whole.
#include "core/image/flip_ldr.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/image/flip.h"
#include "core/image/flip_color.h"
#include "core/image/flip_filter.h"

namespace tp::flip {
namespace {

constexpr float kColorExponent = 0.7f;      // qc
constexpr float kFeatureExponent = 0.5f;    // qf
constexpr float kRedistributeCutoff = 0.4f; // pc: share of cmax ...
constexpr float kRedistributeShare = 0.95f; // pt: ... that gets this share of [0,1]

// The largest perceptible colour distance: HyAB between Hunt-adjusted pure green and blue.
float maxColorDistance() {
    const Vec3 green = linearRgbToHuntLab({0.0f, 1.0f, 0.0f});
    const Vec3 blue = linearRgbToHuntLab({0.0f, 0.0f, 1.0f});
    return std::pow(hyab(green, blue), kColorExponent);
}

inline float redistribute(float powered, float cmax) {
    const float cut = kRedistributeCutoff * cmax;
    return powered < cut ? (kRedistributeShare / cut) * powered
                         : kRedistributeShare +
                               ((powered - cut) / (cmax - cut)) * (1.0f - kRedistributeShare);
}

// The 7 row-filtered planes of one image.
enum Plane { HA, HRG, HBY1, HBY2, HG, HD1, HD2, PlaneCount };
using RowFiltered = std::vector<float>[PlaneCount];

TP_FLIP_SIMD void toOpponent(const float* __restrict r, const float* __restrict g,
                             const float* __restrict b, int w, float* __restrict yy,
                             float* __restrict cx, float* __restrict cz, float* __restrict lum) {
    for (int x = 0; x < w; ++x) {
        const Vec3 c = xyzToYcxcz(linearRgbToXyz({r[x], g[x], b[x]}));
        yy[x] = c.x;
        cx[x] = c.y;
        cz[x] = c.z;
        lum[x] = (c.x + 16.0f) / 116.0f; // the feature detectors' [0,1] achromatic input
    }
}

void rowPass(const LinearPlanes& in, const CsfFilters& csf, const FeatureFilters& feat,
             RowFiltered& out) {
    const int w = in.width;
    for (auto& p : out)
        p.resize(size_t(w) * size_t(in.height));
    parallelRows(in.height, [&](int y0, int y1) {
        const size_t n = static_cast<size_t>(w);
        std::vector<float> yy(n), cx(n), cz(n), lum(n), padded;
        for (int y = y0; y < y1; ++y) {
            const size_t base = size_t(y) * size_t(w);
            toOpponent(&in.r[base], &in.g[base], &in.b[base], w, yy.data(), cx.data(), cz.data(),
                       lum.data());
            auto at = [&](Plane p) { return out[p].data() + base; };
            const Kernel* ka = &csf.achromatic.gaussians[0];
            float* oa = at(HA);
            convolveRow(yy.data(), w, &ka, &oa, 1, padded);
            const Kernel* krg = &csf.redGreen.gaussians[0];
            float* org = at(HRG);
            convolveRow(cx.data(), w, &krg, &org, 1, padded);
            const Kernel* kby[2] = {&csf.blueYellow.gaussians[0], &csf.blueYellow.gaussians[1]};
            float* oby[2] = {at(HBY1), at(HBY2)};
            convolveRow(cz.data(), w, kby, oby, 2, padded);
            const Kernel* kf[3] = {&feat.gaussian, &feat.firstDerivative, &feat.secondDerivative};
            float* of[3] = {at(HG), at(HD1), at(HD2)};
            convolveRow(lum.data(), w, kf, of, 3, padded);
        }
    });
}

// One image's column-filtered row y: the CSF-filtered YyCxCz and the four feature responses.
struct FilteredRow {
    std::vector<float> yy, cx, cz, edgeX, edgeY, pointX, pointY;
    explicit FilteredRow(size_t w)
        : yy(w), cx(w), cz(w), edgeX(w), edgeY(w), pointX(w), pointY(w) {}
};

// Columns [x0, x0 + count) of output row y.
void columnPass(const RowFiltered& in, int w, int h, int x0, int count, int y,
                const CsfFilters& csf, const FeatureFilters& feat, FilteredRow& out) {
    auto plane = [&](Plane p) { return in[p].data() + x0; };
    auto column = [&](Plane p, const Kernel& k, std::vector<float>& o, float scale = 1.0f,
                      bool accumulate = false) {
        convolveColumn(plane(p), w, count, h, y, k, o.data(), scale, accumulate);
    };
    column(HA, csf.achromatic.gaussians[0], out.yy);
    column(HRG, csf.redGreen.gaussians[0], out.cx);
    const CsfFilter& by = csf.blueYellow;
    column(HBY1, by.gaussians[0], out.cz, by.weights[0]);
    column(HBY2, by.gaussians[1], out.cz, by.weights[1], true);
    column(HD1, feat.gaussian, out.edgeX);
    column(HG, feat.firstDerivative, out.edgeY);
    column(HD2, feat.gaussian, out.pointX);
    column(HG, feat.secondDerivative, out.pointY);
}

inline float magnitude(float a, float b) {
    return std::sqrt(a * a + b * b);
}

inline Vec3 filteredToHuntLab(float yy, float cx, float cz) {
    return linearRgbToHuntLab(xyzToLinearRgb(ycxczToXyz({yy, cx, cz})));
}

// The per-pixel part of one row; branch-free so it vectorises (plain restrict pointers: GCC
// does not vectorise loads through a struct's pointer members).
TP_FLIP_SIMD void flipRow(const FilteredRow& refRow, const FilteredRow& testRow, int w, float cmax,
                          float* __restrict out) {
    const float* __restrict ry = refRow.yy.data();
    const float* __restrict rcx = refRow.cx.data();
    const float* __restrict rcz = refRow.cz.data();
    const float* __restrict rex = refRow.edgeX.data();
    const float* __restrict rey = refRow.edgeY.data();
    const float* __restrict rpx = refRow.pointX.data();
    const float* __restrict rpy = refRow.pointY.data();
    const float* __restrict ty = testRow.yy.data();
    const float* __restrict tcx = testRow.cx.data();
    const float* __restrict tcz = testRow.cz.data();
    const float* __restrict tex = testRow.edgeX.data();
    const float* __restrict tey = testRow.edgeY.data();
    const float* __restrict tpx = testRow.pointX.data();
    const float* __restrict tpy = testRow.pointY.data();
    for (int x = 0; x < w; ++x) {
        const float distance = hyab(filteredToHuntLab(ry[x], rcx[x], rcz[x]),
                                    filteredToHuntLab(ty[x], tcx[x], tcz[x]));
        const float colour = redistribute(fastPow(distance, kColorExponent), cmax);
        const float edge = std::abs(magnitude(rex[x], rey[x]) - magnitude(tex[x], tey[x]));
        const float point = std::abs(magnitude(rpx[x], rpy[x]) - magnitude(tpx[x], tpy[x]));
        // ^0.5 (qf) as a square root.
        const float feature = std::sqrt(std::max(edge, point) * 0.707106781f);
        const float v = fastPow(colour, 1.0f - feature);
        out[x] = std::max(out[x], v);
    }
}

} // namespace

void flipLinear(const LinearPlanes& reference, const LinearPlanes& test, float ppd, float* out,
                FlipWorkspace& workspace) {
    static_assert(std::size(FlipWorkspace{}.planes[0]) == PlaneCount);
    const int w = reference.width, h = reference.height;
    const CsfFilters csf = makeCsfFilters(ppd);
    const FeatureFilters feat = makeFeatureFilters(ppd);
    const float cmax = maxColorDistance();
    rowPass(reference, csf, feat, workspace.planes[0]);
    rowPass(test, csf, feat, workspace.planes[1]);
    // Whole rows: strips of 256 columns (to keep the 21 rows a column filter reads in the
    // core's cache) measured slower here, the prefetcher likes long rows better.
    parallelRows(h, [&](int y0, int y1) {
        FilteredRow ref(static_cast<size_t>(w)), tst(static_cast<size_t>(w));
        for (int y = y0; y < y1; ++y) {
            columnPass(workspace.planes[0], w, h, 0, w, y, csf, feat, ref);
            columnPass(workspace.planes[1], w, h, 0, w, y, csf, feat, tst);
            flipRow(ref, tst, w, cmax, out + size_t(y) * size_t(w));
        }
    });
}

} // namespace tp::flip

namespace tp {
namespace {

// Display RGB (sRGB-encoded) to linear planes; non-finite as black, clamped to [0,1] first
// as an 8-bit file would be.
flip::LinearPlanes decodeDisplay(const ImageRGBA& display) {
    flip::LinearPlanes p(int(display.width), int(display.height));
    std::vector<float>* planes[3] = {&p.r, &p.g, &p.b};
    for (size_t i = 0; i < display.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = display.rgba[i * 4 + size_t(c)];
            (*planes[c])[i] =
                flip::srgbToLinear(std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f);
        }
    return p;
}

} // namespace

FlipResult ldrFlip(const ImageRGBA& testDisplay, const ImageRGBA& referenceDisplay, float ppd) {
    FlipResult result;
    if (testDisplay.width != referenceDisplay.width ||
        testDisplay.height != referenceDisplay.height || testDisplay.pixelCount() == 0)
        return result;
    result.map = {testDisplay.width, testDisplay.height,
                  std::vector<float>(testDisplay.pixelCount())};
    flip::FlipWorkspace workspace;
    flip::flipLinear(decodeDisplay(referenceDisplay), decodeDisplay(testDisplay), ppd,
                     result.map.r.data(), workspace);
    result.stats = poolFlip(result.map);
    return result;
}

} // namespace tp
