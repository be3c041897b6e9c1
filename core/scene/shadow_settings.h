#pragma once
// --shadows / --shadow-budget / --shadow-cache (docs/shadows.md): which of the scene's lights
// cast shadows is the run's, not a pipeline's: every pipeline and the reference shadow the same
// ones. It sits with the scene, below everything that reads it, because a stress case (a scene
// and how it is run: core/scene/stress_scenes.h) carries one. Parsed from the command line in
// core/cli/shadow_option.h; planned into maps in core/passes/shadow_planner.h.
#include <cstdint>
#include <stdexcept>

namespace tp {

struct ShadowSettings {
    uint32_t count = 0; // shadowed lights (0: none)
    bool all = false;   // every light that reaches the view
    uint32_t budgetMb = 256;
    // The atlas rendered once and kept while the shadowed lights and the geometry stay (the
    // per-light residency cannot: it renders over its one map): --shadow-cache on|off.
    bool cache = true;
    bool enabled() const { return all || count > 0; }
    bool operator==(const ShadowSettings&) const = default;
};

// Settings this scene and view cannot honour: the budget cannot hold the lights' maps even at
// their smallest. Known only once the view is planned, so it is thrown there (the planner) and
// caught at the CLI boundary (app/main.cpp: one line, exit code 2).
struct ShadowError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace tp
