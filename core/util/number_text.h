#pragma once
// The short form of a number in every text triptych writes for a person: report pages and
// plots, and the limits a stress check states in its reason (both must read alike).
#include <string>

namespace tp {

// 4 significant digits, an exponent (3 digits) when very small or large; "inf", "-inf", "nan".
std::string formatNumber(double v);

} // namespace tp
