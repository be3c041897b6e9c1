#pragma once
// What `compare` says on the terminal at the end of a run: the summary table (frame time,
// memory, the error figures beside each other, a mark where one pixel decides the RMSE) and
// a warning for anything a pipeline counted as dropped.
#include "compare/report/report_json.h"

namespace tp::cli {

void printSummary(const CompareRecord& r);
// Anything a pipeline counted as dropped (lights_dropped, transparent_lights_dropped,
// blended_fragments_dropped, ...) is said on stderr, not only in the counters.
void warnDropped(const PipelineOutcome& p);

} // namespace tp::cli
