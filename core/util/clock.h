#pragma once
// Wall-clock time since a steady_clock instant, in the units the callers report.
#include <chrono>

namespace tp {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline double msSince(std::chrono::steady_clock::time_point start) {
    return 1000.0 * secondsSince(start);
}

} // namespace tp
