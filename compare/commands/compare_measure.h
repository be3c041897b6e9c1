#pragma once
// compare's measurements of its images (internal to triptych compare, cmd_compare.cpp): every
// pipeline against the reference and the pipelines against each other, with the difference
// and FLIP maps written into the output folder.
#include <string>

#include "compare/report/report_json.h"

namespace tp::cli {

// Files of the pair (a, b): the signed difference a - b.
std::string pairDiffStem(const std::string& a, const std::string& b);

// Every pipeline that ran against the reference (r.reference ran): metrics linear and
// tonemapped, FLIP, the difference's 99th percentile; sets r.diffScale, the one heat-map scale
// of the report (the largest of those percentiles), and writes each pipeline's difference and
// FLIP maps into `out` (the FLIP maps are then let go).
void measureAgainstReference(CompareRecord& r, const std::string& out);

// Pipelines against each other: metrics of a against b, and the signed difference a - b as
// EXR and heat map on r.diffScale (set by measureAgainstReference), into `out`.
void measurePairs(CompareRecord& r, const std::string& out);

} // namespace tp::cli
