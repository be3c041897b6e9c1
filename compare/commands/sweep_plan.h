#pragma once
// The runs a sweep makes (internal to triptych sweep, cmd_sweep.cpp): its comma-separated
// lists read and checked before any GPU work, and the knob combinations each pipeline runs.
#include <string>
#include <vector>

#include "compare/commands/sweep.h"
#include "core/renderer/settings.h"

namespace tp::cli {

// "a,b,c" as its non-empty items; UsageError naming `option` for an empty list.
std::vector<std::string> splitList(const std::string& text, const char* option);
// A count in [0, 1000000]; UsageError naming `option` otherwise.
int toInt(const std::string& s, const char* option);

// Every value of every swept knob against its declaration, before anything runs. Single values
// (knobs the sweep does not vary) are checked by the CLI, like every command's knobs.
void checkKnobLists(const SweepOptions& o);
// The settings `pipeline` runs with over `base` (one view): once per value of the knobs it
// reads, with the first value of the others, so the sweep repeats no identical run.
std::vector<RenderSettings> knobCombos(const std::string& pipeline, const SweepOptions& o,
                                       const RenderSettings& base);

} // namespace tp::cli
