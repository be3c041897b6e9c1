#pragma once
// compare's measurements of its images (internal to triptych compare, cmd_compare.cpp): every
// pipeline against the reference and the pipelines against each other, with the difference
// and FLIP maps written into the output folder.
#include <string>

#include "compare/measure/flip_measure.h"
#include "compare/report/report_json.h"
#include "core/image/metrics.h"

namespace tp::cli {

// Files of the pair (a, b): the signed difference a - b.
std::string pairDiffStem(const std::string& a, const std::string& b);

// Every pipeline that ran against the reference: metrics linear and tonemapped, FLIP, the
// difference's 99th percentile, one pipeline at a time as its run ends (measure(): each index
// once, from any thread, while no other call touches that pipeline); then write() sets
// r.diffScale, the one heat-map scale of the report (the largest of those percentiles), and
// writes each pipeline's difference and FLIP maps into `out` (the FLIP maps are then let go).
class ReferenceMeasures {
  public:
    // After the reference ran and r.exposureEv and r.hdrPsnrPeak are set; `pipelines`: how
    // many r.pipelines will hold.
    ReferenceMeasures(const CompareRecord& r, size_t pipelines);
    void measure(PipelineOutcome& p, size_t index);
    void write(CompareRecord& r, const std::string& out);

  private:
    const ImageRGBA& reference_;
    float exposureEv_;
    MetricsOptions hdrOptions_;
    ImageRGBA referenceDisplay_;
    FlipReference flipReference_;
    std::vector<ImageRGBA> diffs_; // each pipeline's signed difference, by index
};

// Pipelines against each other: metrics of a against b, and the signed difference a - b as
// EXR and heat map on r.diffScale (set by measureAgainstReference), into `out`.
void measurePairs(CompareRecord& r, const std::string& out);

} // namespace tp::cli
