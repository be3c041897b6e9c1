// stress.json: every figure and verdict of a stress run, and the command to repeat it.
#include "compare/report/stress_report.h"

#include "compare/report/run_json.h"
#include "core/cli/shadow_option.h"
#include "core/renderer/error_model.h"

namespace tp::cli {
namespace {

using nlohmann::json;

std::string quoted(const std::vector<std::string>& args) {
    std::string out;
    for (const std::string& a : args)
        out +=
            (out.empty() ? "" : " ") +
            (!a.empty() && a.find_first_of(" \t\"'\\$`") == std::string::npos ? a : "'" + a + "'");
    return out;
}

json boundJson(const ErrorBound& b, float ev) {
    json terms = json::array();
    for (const BoundTerm& t : b.terms)
        terms.push_back(
            {{"name", t.name}, {"relative", t.relative}, {"absolute", t.absolute}, {"why", t.why}});
    json j = {{"bounded", b.bounded}, {"why", b.why}, {"terms", terms}};
    if (b.bounded) {
        j["relative"] = b.relative();
        j["absolute"] = b.absolute();
        j["tonemapped"] = b.tonemapped(ev);
    }
    return j;
}

json checksJson(const std::vector<StressCheck>& checks) {
    json out = json::array();
    for (const StressCheck& c : checks)
        out.push_back({{"name", c.name},
                       {"pass", c.pass},
                       {"measured", c.measured},
                       {"limit", c.limit},
                       {"why", c.why}});
    return out;
}

json outcomeJson(const StressOutcome& p, const GpuContext& ctx, float ev, bool reference) {
    json j = {{"name", p.name}, {"status", p.run ? "ok" : "failed"}, {"files", p.files}};
    if (!p.run) j["error"] = p.error;
    if (!reference) {
        j["verdict"] = p.pass ? "pass" : "fail";
        j["checks"] = checksJson(p.checks);
    }
    j["nan_pixels"] = p.nanPixels;
    j["inf_pixels"] = p.infPixels;
    if (p.inertChecked) j["inert_changed_pixels"] = p.inertChanged;
    if (!p.run) return j;
    j["run"] = runJson(*p.run, ctx);
    if (reference) return j;
    j["bound"] = boundJson(p.bound, ev);
    j["error_vs_reference"] = {{"hdr", metricsJson(p.hdr)}, {"tonemapped", metricsJson(p.display)}};
    j["max_tonemapped"] = p.rawMaxTonemapped;
    j["checked_max_tonemapped"] = p.checkedMaxTonemapped;
    if (p.bound.bounded && p.hdrBeyondBound >= 0) j["hdr_beyond_bound"] = p.hdrBeyondBound;
    if (!p.bound.perPixel.name.empty())
        j["per_pixel_allowance"] = {{"name", p.bound.perPixel.name},
                                    {"why", p.bound.perPixel.why},
                                    {"widened_pixels", p.allowancePixels},
                                    {"unchecked_pixels", p.unboundedPixels}};
    j["lights_dropped"] = p.lightsDropped;
    j["fp16_storage"] = p.fp16Storage;
    j["beyond_half_float"] = {{"reference_channels", p.overflowChannels},
                              {"saturated", p.saturated},
                              {"inf", p.overflowInf},
                              {"behaviour", overflowBehaviour(p)}};
    j["depth_mismatch_pixels"] = p.depthMismatch;
    j["difference_p99"] = p.diffP99;
    return j;
}

// A shadowed case: the exact reference and the maps reference's verdict against it.
json shadowJson(const ShadowTechnique& t, const GpuContext& ctx, float ev) {
    json j = {{"reference_rays", outcomeJson(t.rays, ctx, ev, true)},
              {"verdict", t.pass ? "pass" : "fail"},
              {"checks", checksJson(t.checks)}};
    if (t.rays.run)
        j["maps_vs_rays"] = {{"hdr", metricsJson(t.hdr)}, {"tonemapped", metricsJson(t.display)}};
    return j;
}

json caseJson(const StressCaseResult& r, const GpuContext& ctx) {
    json pipelines = json::array();
    for (const StressOutcome& p : r.pipelines)
        pipelines.push_back(outcomeJson(p, ctx, r.exposureEv, false));
    json j = {{"name", r.c->name},
            {"stresses", r.c->stresses},
            {"expectation", r.c->expectation},
            {"verdict", r.pass ? "pass" : "fail"},
            {"seconds", r.seconds},
            {"lights", r.lights},
            {"triangles", r.triangles},
            {"settings", settingsJson(r.settings)},
            {"exposure_ev", r.exposureEv},
            {"difference_scale",
             {{"value", r.diffScale},
              {"unit", "linear radiance, max over RGB"},
              {"rule", "largest 99th percentile of |pipeline - reference| over the pipelines"}}},
            {"reference", outcomeJson(r.reference, ctx, r.exposureEv, true)},
            {"pipelines", pipelines}};
    if (r.c->shadows.enabled()) {
        j["shadows"] = shadowCountText(r.c->shadows);
        j["reference"]["shadows"] = "maps";
        if (r.shadow) j["shadow_technique"] = shadowJson(*r.shadow, ctx, r.exposureEv);
    }
    return j;
}

} // namespace

json stressJson(const std::vector<std::string>& commandLine, const GpuContext& ctx,
                const std::vector<StressCaseResult>& results,
                const std::vector<std::string>& validationMessages) {
    json cases = json::array(), failures = json::array();
    size_t passed = 0;
    for (const StressCaseResult& r : results) {
        cases.push_back(caseJson(r, ctx));
        passed += r.pass;
        for (const StressOutcome& p : r.pipelines)
            for (const StressCheck& c : p.checks)
                if (!c.pass) failures.push_back(r.c->name + "/" + p.name + ": " + c.name);
        if (!r.reference.run) failures.push_back(r.c->name + "/reference: " + r.reference.error);
        if (r.shadow)
            for (const StressCheck& c : r.shadow->checks)
                if (!c.pass) failures.push_back(r.c->name + "/shadow technique: " + c.name);
    }
    json j;
    j["schema"] = "triptych.stress/2";
    j["command_line"] = commandLine;
    j["command"] = quoted(commandLine);
    j["status"] = passed == results.size() ? "pass" : "fail";
    j["device"] = deviceJson(ctx);
    // Deferred's per-pixel allowance depends on it (docs/stress.md, "Position from depth next to a
    // light").
    j["device"]["sub_pixel_precision_bits"] = ctx.properties.limits.subPixelPrecisionBits;
    j["tonemap_slopes"] = {{"relative_K", tonemapRelativeSlope()},
                           {"absolute_S0", tonemapAbsoluteSlope()},
                           {"rule", "tonemapped bound = K * relative + S0 * 2^ev * absolute"}};
    j["summary"] = {{"cases", results.size()},
                    {"passed", passed},
                    {"failed", results.size() - passed},
                    {"failures", failures}};
    j["validation_messages"] = validationMessages;
    j["cases"] = cases;
    j["files"] = {"stress.json", "stress.html"};
    return j;
}

} // namespace tp::cli
