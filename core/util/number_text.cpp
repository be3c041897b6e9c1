#include "core/util/number_text.h"

#include <cmath>
#include <cstdio>

namespace tp {

std::string formatNumber(double v) {
    char buf[32];
    if (!std::isfinite(v)) return v > 0 ? "inf" : (v < 0 ? "-inf" : "nan");
    double a = std::abs(v);
    if (a != 0.0 && (a < 1e-3 || a >= 1e6))
        std::snprintf(buf, sizeof buf, "%.2e", v);
    else
        std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

} // namespace tp
