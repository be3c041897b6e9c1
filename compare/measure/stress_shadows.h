#pragma once
// The shadowed cases of triptych stress (StressCase::shadows; docs/stress.md, "Shadowed
// cases"): the pipelines are measured, with their usual error models, against the reference
// that samples the same shadow maps (--reference-shadows maps); the shadow technique itself
// is judged on that reference against the exact one (rays), with bounds derived from the
// maps' texel footprint and the filter (include/shadows.h). Internal to triptych stress.
#include <string>

#include "compare/measure/stress_case.h"
#include "core/gpuscene/shadow_plan.h"

namespace tp::cli {

inline constexpr const char* kReferenceShadowsKnob = "reference-shadows";
inline constexpr const char* kReferenceShadowMaps = "maps";
inline constexpr const char* kReferenceShadowRays = "rays";

// Empty when the registered reference offers --reference-shadows maps and rays; else why not
// (a build from before the shadow references: the case cannot be judged).
std::string missingShadowReferences();

// `s` with the reference's shadow visibility set to `value` (maps or rays).
RenderSettings withReferenceShadows(RenderSettings s, const char* value);

// Fills r.shadow's comparison, checks and verdict from the two references (both ran, r.shadow
// holds the rays one), the case's facts and the shadow plan the run used.
void measureShadowTechnique(StressCaseResult& r, const Scene& scene, const ShadowPlan& plan);

// The check every pipeline gets in a shadowed case: its shadowed_lights counter (ShadowMaps::
// counters) at least the case's count. Unlike CounterAtLeast, a pipeline without the counter
// fails it: it did not render the shadows the case asks for.
StressCheck shadowedLightsCheck(const RunResult& run, const stress::StressCase& c);

} // namespace tp::cli
