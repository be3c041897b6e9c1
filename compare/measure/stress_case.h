#pragma once
// What triptych stress measured of one case (docs/stress.md): each pipeline's outcome against
// the reference, its checks and verdict, and for shadowed cases the shadow technique's. Made by
// compare/measure/stress_measure.h and stress_shadows.h, written by compare/report/stress_report.h.
#include <optional>
#include <string>
#include <vector>

#include "core/image/metrics.h"
#include "core/renderer/error_model.h"
#include "core/runner/frame_runner.h"
#include "core/scene/stress_scenes.h"

namespace tp::cli {

// One verdict ingredient: `measured` against `limit` (pass when measured <= limit, or
// >= for the checks named "stressed: ...").
struct StressCheck {
    std::string name;
    bool pass = true;
    double measured = 0;
    double limit = 0;
    std::string why;
};

struct StressOutcome {
    std::string name;
    std::string error; // empty when it ran
    std::optional<RunResult> run;
    ErrorReport hdr, display; // against the reference, whole image
    uint64_t nanPixels = 0, infPixels = 0;
    // Channels where the reference exceeds the fp16 maximum 65,504, and what this pipeline
    // wrote there: about 65,504 (saturated), +Inf, or a value within the bound.
    uint64_t overflowChannels = 0, saturated = 0, overflowInf = 0;
    bool fp16Storage = false;   // its "hdr" target is RGBA16F (from the memory ledger)
    uint64_t depthMismatch = 0; // pixels whose depth differs from the reference's
    // Cases with inert lights (StressCase::inertLights): pixels whose colour bits differ from
    // the same renderer's image of the twin scene, where those lights have intensity 0.
    bool inertChecked = false;
    uint64_t inertChanged = 0;
    // Cases checked on HDR values (StressCase::hdrChecked): max over pixels and channels of
    // (|p - r| less the pixel's allowance) / (relative * |r| + absolute); pass at <= 1.
    double hdrBeyondBound = -1; // -1: not checked
    double lightsDropped = 0;
    double rawMaxTonemapped = 0;     // |T(p) - T(r)| max outside the fp16-overflow channels
    double checkedMaxTonemapped = 0; // the same less each pixel's allowance (ErrorBound::perPixel)
    uint64_t allowancePixels = 0;    // pixels the allowance widened
    uint64_t unboundedPixels = 0;    // pixels the allowance leaves unchecked (+Inf)
    ErrorBound bound;
    std::vector<StressCheck> checks;
    bool pass = false;
    float diffP99 = 0;
    std::vector<std::string> files; // relative to --out
};

// A shadowed case's second reference and the shadow technique's verdict: the reference on the
// pipelines' shadow maps (StressCaseResult::reference) against the exact one (`rays`), checked
// against the case's facts (stress::ShadowFacts; compare/measure/stress_shadows.h).
struct ShadowTechnique {
    StressOutcome rays; // the reference with --reference-shadows rays
    ErrorReport hdr, display; // the maps reference against the rays reference
    std::vector<StressCheck> checks;
    bool pass = false;
};

struct StressCaseResult {
    const stress::StressCase* c = nullptr;
    size_t lights = 0, triangles = 0;
    RenderSettings settings;
    float exposureEv = 0;
    float diffScale = 0;
    uint32_t subPixelBits = 8; // the device's VkPhysicalDeviceLimits::subPixelPrecisionBits
    double seconds = 0;
    StressOutcome reference;
    std::vector<StressOutcome> pipelines;
    std::optional<ShadowTechnique> shadow; // shadowed cases (StressCase::shadows)
    bool pass = false;
};

// "fp16 storage behaviour" of an outcome as one phrase for the report.
std::string overflowBehaviour(const StressOutcome& p);

} // namespace tp::cli
