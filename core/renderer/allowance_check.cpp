// The tonemapped error left after each pixel's allowance (core/renderer/error_model.h).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/renderer/error_model.h"
#include "include/tonemap.h"

namespace tp {

// Per channel, the allowance a explains T(r + a) - T(r) or T(r) - T(r - a), whichever side
// p is on (T is monotone per channel); only what is left beyond it counts.
AllowanceCheck errorBeyondAllowance(const ErrorBound& bound, const ImageRGBA& pipeline,
                                    const ImageRGBA& reference, float ev) {
    const ImageR32& a = bound.perPixel.radiance;
    const bool any = !a.r.empty() && a.r.size() == reference.pixelCount();
    AllowanceCheck out;
    for (size_t i = 0; i < reference.pixelCount(); ++i) {
        const float allow = any ? a.r[i] : 0.0f;
        if (std::isinf(allow)) {
            ++out.unboundedPixels;
            continue;
        }
        out.widenedPixels += allow > 0.0f;
        const float* pv = &pipeline.rgba[i * 4];
        const float* rv = &reference.rgba[i * 4];
        const gpu::vec3 r(rv[0], rv[1], rv[2]);
        const gpu::vec3 tp = gpu::tonemap(gpu::vec3(pv[0], pv[1], pv[2]), ev);
        const gpu::vec3 tr = gpu::tonemap(r, ev);
        const gpu::vec3 hi = allow > 0 ? gpu::tonemap(r + gpu::vec3(allow), ev) : tr;
        const gpu::vec3 lo =
            allow > 0 ? gpu::tonemap(max(r - gpu::vec3(allow), gpu::vec3(0.0f)), ev) : tr;
        for (int c = 0; c < 3; ++c) {
            const double d = double(tp[c]) - double(tr[c]);
            if (std::isnan(d)) {
                out.worstBeyond = std::numeric_limits<double>::infinity();
                return out; // as stress always did: the counts stop here too
            }
            const double explained =
                d > 0 ? double(hi[c]) - double(tr[c]) : double(tr[c]) - double(lo[c]);
            if (std::abs(d) - explained > out.worstBeyond) {
                out.worstBeyond = std::abs(d) - explained;
                out.worstPixel = i;
            }
        }
    }
    return out;
}

} // namespace tp
