#pragma once
// What `triptych stress` expects of each pipeline in each case: a per-pixel error bound
// against the reference derived from how the pipeline computes (storage formats, summation,
// G-buffer quantization), never from what it printed. docs/stress.md explains each term.
//
// The bound is |pipeline - reference| <= relative * |reference| + absolute per HDR channel.
// The verdict checks it on tonemapped values (what a user sees, and where a relative bound
// stays meaningful next to black pixels): the tonemap T (one exposure for both images)
// changes by at most K * relative + S0 * 2^ev * absolute, with
//   K  = sup_x x * T'(x)  (a relative change of x moves T by at most K times it),
//   S0 = sup_x T'(x)      (an absolute change of x moves T by at most S0 times it),
// both computed here from the tonemap operator itself (shaders/include/tonemap.h).
#include <string>
#include <vector>

#include "core/render/settings.h"
#include "core/scene/scene.h"
#include "core/scene/stress_scenes.h"

namespace tp::cli {

struct BoundTerm {
    std::string name;
    double relative = 0;
    double absolute = 0;
    std::string why;
};

struct ErrorBound {
    bool bounded = true; // false: the method gives no per-pixel bound here (`why` says so)
    std::string why;
    std::vector<BoundTerm> terms;
    double relative() const;
    double absolute() const;
    // Largest allowed |T(pipeline) - T(reference)| per channel at exposure `ev`.
    double tonemapped(float ev) const;
};

// K and S0 of the header comment, from the tonemap at exposure 0 (K does not depend on
// exposure; S0 scales with 2^ev).
double tonemapRelativeSlope();
double tonemapAbsoluteSlope();

// The bound for `pipeline` in `c`, whose scene is `scene`, rendered with `s`.
ErrorBound expectedBound(const std::string& pipeline, const stress::StressCase& c, const Scene& scene,
                         const RenderSettings& s);

} // namespace tp::cli
