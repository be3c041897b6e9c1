// triptych stress end to end, validation on: every case through every registered pipeline,
// the report written, a verdict per case and pipeline, and the verdicts those of today:
// every pair passes except the known failures below, each listed with the bug it shows.
// When a bug is fixed its entry must go (the test fails on an unexpected pass too), so the
// list stays the truth.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "compare/commands/stress_run.h"
#include "core/renderer/pipeline_colour.h"
#include "core/renderer/renderer.h"
#include "core/scene/stress_scenes.h"
#include "core/util/files.h"
#include "temp_path.h"

namespace tp::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// "case/pipeline" -> why it fails today (docs/stress.md, "Known failures").
const std::map<std::string, std::string>& knownFailures() {
    // Empty since shading became camera-relative (docs/shading.md): far-from-origin
    // (deferred, multipass) and light-on-surface (deferred) pass; docs/stress.md says how
    // robust each pass is. The shadowed cases pass for every pipeline (each consumes
    // --shadows: issue 26, item 2).
    static const std::map<std::string, std::string> known = {
        {"light-hugging-far/deferred",
         "position from depth on a floor seen at 5.7 degrees 22 m away, 0.1 mm under a light: "
         "0.00216 beyond the per-pixel allowance against 0.00182 on lavapipe; the allowance "
         "(the snapped vertices' displacement) lacks a term the reconstruction has there "
         "(issue 40: found with the visibility buffer's position case, not yet derived)"}};
    return known;
}

// "case/pipeline" -> why its verdict changes from run to run today: either verdict is
// accepted (and printed), so the suite stays honest without hiding the bug.
const std::map<std::string, std::string>& knownFlaky() {
    // None today (lights-65536/deferred was one until the tiled lighting took its lights in
    // batches: docs/deferred.md, "Tiled lighting").
    static const std::map<std::string, std::string> flaky = {};
    return flaky;
}

json readJson(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return json::parse(ss.str());
}

bool hasCheck(const json& p, const std::string& prefix) {
    for (const json& k : p["checks"])
        if (k["name"].get<std::string>().starts_with(prefix)) return true;
    return false;
}

// What a case states (StressCase) must show up as checks and bound terms, so a fact cannot
// silently stop being checked.
void expectFactChecks(const stress::StressCase& sc, const json& p, const std::string& key) {
    EXPECT_EQ(hasCheck(p, "pixels the inert lights change"), sc.inertLights > 0) << key;
    EXPECT_EQ(hasCheck(p, "HDR max"), sc.hdrChecked) << key;
    EXPECT_EQ(hasCheck(p, "stressed: shadowed_lights"), sc.shadows.enabled()) << key;
    if (sc.blendedLayers) {
        bool term = false;
        for (const json& t : p["bound"]["terms"])
            term |= t["name"] == "blended layers: fp32 blend arithmetic";
        EXPECT_TRUE(term) << key;
    }
}

// A shadowed case's technique verdict (the maps reference against the rays one) is a pass,
// with a check for each fact the case states. Returns the verdict.
bool expectShadowTechniquePasses(const stress::StressCase& sc, const json& c) {
    const std::string name = c["name"];
    EXPECT_TRUE(c.contains("shadow_technique")) << name;
    if (!c.contains("shadow_technique")) return false;
    const json& t = c["shadow_technique"];
    EXPECT_EQ(t["reference_rays"]["status"], "ok") << name;
    const stress::ShadowFacts& f = sc.shadowFacts;
    EXPECT_TRUE(hasCheck(t, "stressed: lights the plan shadows")) << name;
    EXPECT_EQ(hasCheck(t, "acne:"), f.floorAcne) << name;
    EXPECT_EQ(hasCheck(t, "peter-panning:"), f.wallLight >= 0) << name;
    EXPECT_EQ(hasCheck(t, "light in the box:"), f.boxLight >= 0) << name;
    std::string failed;
    for (const json& k : t["checks"])
        if (!k["pass"].get<bool>())
            failed += k["name"].get<std::string>() + " " + k["measured"].dump() + " vs " +
                      k["limit"].dump() + "; ";
    EXPECT_EQ(t["verdict"].get<std::string>(), "pass") << name << " shadow technique: " << failed;
    return t["verdict"] == "pass";
}

// Every pipeline's verdict on case `c` is a pass; a failure names the checks that failed.
void expectEveryPipelinePasses(const json& c) {
    for (const json& p : c["pipelines"]) {
        std::string failed;
        for (const json& k : p["checks"])
            if (!k["pass"].get<bool>())
                failed += k["name"].get<std::string>() + " " + k["measured"].dump() + " > " +
                          k["limit"].dump() + "; ";
        EXPECT_EQ(p["verdict"], "pass") << c["name"].get<std::string>() << "/"
                                        << p["name"].get<std::string>() << ": " << failed;
    }
}

TEST(Stress, EveryCaseGivesTodaysVerdicts) {
    cli::StressOptions o;
    o.out = freshDir("stress");
    o.device.validate = true;
    o.commandLine = {"triptych", "stress", "--validate", "--out", o.out};
    const int code = cli::runStress(o);
    EXPECT_NE(code, 3) << "validation messages: see stress.json";
    // 6 exactly when some case failed (checked against the verdicts below).
    EXPECT_TRUE(code == 0 || code == 6) << code;
    ASSERT_TRUE(fs::exists(o.out + "/stress.json"));
    ASSERT_TRUE(fs::exists(o.out + "/stress.html"));
    const json r = readJson(o.out + "/stress.json");
    EXPECT_EQ(r["schema"], "triptych.stress/2");
    EXPECT_TRUE(r["validation_messages"].empty());
    ASSERT_EQ(r["cases"].size(), stress::stressCases().size());

    std::vector<std::string> pipelines;
    for (const RendererEntry& e : registeredRenderers())
        if (e.name != "reference") pipelines.push_back(e.name);
    // Each pipeline is named in the colour it has on every page (core/renderer/pipeline_colour.h).
    Result<std::string> html = readWholeFile(o.out + "/stress.html");
    ASSERT_TRUE(html.ok());
    for (const std::string& name : pipelines)
        EXPECT_NE(html->find(std::string("background:") + paletteHex(pipelineColour(name)) +
                             "\"></span>" + name),
                  std::string::npos)
            << name;
    bool anyFail = false;
    for (const json& c : r["cases"]) {
        const std::string name = c["name"];
        EXPECT_EQ(c["reference"]["status"], "ok") << name;
        const stress::StressCase& sc = *(*stress::selectStressCases(name)).front();
        if (sc.inertLights) {
            EXPECT_EQ(c["reference"]["inert_changed_pixels"], 0) << name;
        }
        EXPECT_TRUE(fs::exists(o.out + "/" + name + "/reference.png")) << name;
        ASSERT_EQ(c["pipelines"].size(), pipelines.size()) << name;
        bool casePass = true;
        for (size_t i = 0; i < pipelines.size(); ++i) {
            const json& p = c["pipelines"][i];
            const std::string key = name + "/" + pipelines[i];
            EXPECT_EQ(p["name"], pipelines[i]);
            ASSERT_TRUE(p["verdict"] == "pass" || p["verdict"] == "fail") << key;
            EXPECT_FALSE(p["checks"].empty()) << key;
            if (p["status"] == "ok") expectFactChecks(sc, p, key);
            const bool expectFail = knownFailures().count(key) > 0;
            std::string failed;
            for (const json& k : p["checks"])
                if (!k["pass"].get<bool>())
                    failed += k["name"].get<std::string>() + " " + k["measured"].dump() + " > " +
                              k["limit"].dump() + "; ";
            if (knownFlaky().count(key))
                std::printf("stress: %s (known flaky): %s %s\n", key.c_str(),
                            p["verdict"].get<std::string>().c_str(), failed.c_str());
            else
                EXPECT_EQ(p["verdict"], expectFail ? "fail" : "pass")
                    << key
                    << (expectFail ? ": a known failure passes now; remove it from knownFailures()"
                                   : ": " + failed);
            casePass &= p["verdict"] == "pass";
            if (p["status"] == "ok") {
                EXPECT_TRUE(fs::exists(o.out + "/" + name + "/" + pipelines[i] + ".exr")) << key;
                EXPECT_TRUE(fs::exists(o.out + "/" + name + "/" + pipelines[i] + "_diff.png"))
                    << key;
            }
        }
        if (sc.shadows.enabled()) casePass &= expectShadowTechniquePasses(sc, c);
        EXPECT_EQ(c["verdict"], casePass ? "pass" : "fail") << name;
        anyFail |= !casePass;
    }
    EXPECT_EQ(code, anyFail ? 6 : 0);
    EXPECT_EQ(r["summary"]["failed"].get<int>() > 0, anyFail);
    fs::remove_all(o.out);
}

// Clustered light assignment (--light-assign clustered) on the cases that stress light
// assignment, through both pipelines that have it: every verdict must pass, with the same
// error models (bounds) as tiled.
TEST(Stress, ClusteredPassesTheLightAssignmentCases) {
    cli::StressOptions o;
    o.out = freshDir("stress_clustered");
    o.device.validate = true;
    o.cases = "tile-overflow,depth-discontinuity,lights-65536,lights-whole-screen,lights-subpixel,"
              "far-from-origin";
    o.pipelines = "forwardplus,deferred";
    o.knobs.set("light-assign", "clustered");
    o.commandLine = {"triptych",  "stress", "--validate", "--light-assign",
                     "clustered", "--out",  o.out};
    const int code = cli::runStress(o);
    ASSERT_TRUE(fs::exists(o.out + "/stress.json"));
    const json r = readJson(o.out + "/stress.json");
    EXPECT_TRUE(r["validation_messages"].empty());
    EXPECT_EQ(r["cases"].size(), 6u);
    for (const json& c : r["cases"])
        expectEveryPipelinePasses(c);
    EXPECT_EQ(code, 0);
    fs::remove_all(o.out);
}

// Shadow maps rasterized in compute (--shadow-raster compute), judged against the maps
// reference: its maps are rasterized the same way (core/reference/reference_settings.h), so a
// texel the compute rasterizer stores differently from the hardware is in both images. With
// hardware maps in the reference, Forward+ failed shadowed-256 by exactly such texels
// (tonemapped max |p - r| 3.38e-4 against its limit 3.20e-4).
TEST(Stress, ComputeShadowMapsPassTheShadowedCase) {
    cli::StressOptions o;
    o.out = freshDir("stress_compute_maps");
    o.device.validate = true;
    o.cases = "shadowed-256";
    o.pipelines = "forwardplus";
    o.knobs.set("cull-geometry", "frustum");
    o.knobs.set("shadow-raster", "compute");
    o.commandLine = {"triptych", "stress", "--validate", "--cull-geometry", "frustum",
                     "--shadow-raster", "compute", "--case", o.cases, "--out", o.out};
    const int code = cli::runStress(o);
    ASSERT_TRUE(fs::exists(o.out + "/stress.json"));
    const json r = readJson(o.out + "/stress.json");
    EXPECT_TRUE(r["validation_messages"].empty());
    ASSERT_EQ(r["cases"].size(), 1u);
    expectEveryPipelinePasses(r["cases"][0]);
    EXPECT_EQ(code, 0);
    fs::remove_all(o.out);
}

// The stiff cases of issue 29 (a 10^9 range, 64 blended layers, lights of range 0, the eye
// inside lights, zero cones) through the pipelines' other modes: deferred's light volumes
// (the eye inside a sphere and at a cone's apex; a zero-radius volume) with its wide
// G-buffer and fp16 hdr, Forward+'s fixed lists, multipass forward's fp16 accumulation and
// textbook blended light passes. Every verdict must pass, the inert lights' bit-for-bit check
// included, with the bounds each model derives for these knobs.
TEST(Stress, StiffCasesPassInTheOtherModes) {
    cli::StressOptions o;
    o.out = freshDir("stress_modes");
    o.device.validate = true;
    o.cases = "dynamic-range,blended-64,lights-range-0,camera-in-light,spot-zero-cone";
    const std::vector<std::pair<std::string, std::string>> knobs = {
        {"deferred-lighting", "volumes"}, {"gbuffer", "wide"}, {"hdr", "fp16"},
        {"light-lists", "fixed"},         {"accum", "fp16"},   {"blended-lights", "additive"}};
    o.commandLine = {"triptych", "stress", "--validate"};
    for (const auto& [k, v] : knobs) {
        o.knobs.set(k, v);
        o.commandLine.insert(o.commandLine.end(), {"--" + k, v});
    }
    o.commandLine.insert(o.commandLine.end(), {"--case", o.cases, "--out", o.out});
    const int code = cli::runStress(o);
    ASSERT_TRUE(fs::exists(o.out + "/stress.json"));
    const json r = readJson(o.out + "/stress.json");
    EXPECT_TRUE(r["validation_messages"].empty());
    EXPECT_EQ(r["cases"].size(), 5u);
    for (const json& c : r["cases"]) {
        if (c["name"] == "lights-range-0" || c["name"] == "spot-zero-cone") {
            EXPECT_EQ(c["reference"]["inert_changed_pixels"], 0) << c["name"];
        }
        expectEveryPipelinePasses(c);
    }
    EXPECT_EQ(code, 0);
    fs::remove_all(o.out);
}

TEST(Stress, UnknownCaseIsRefusedBeforeWriting) {
    cli::StressOptions o;
    o.out = freshDir("stress_bad");
    o.cases = "tile-overflow,no-such-case";
    EXPECT_THROW(cli::runStress(o), cli::UsageError);
    EXPECT_FALSE(fs::exists(o.out));
}

} // namespace
} // namespace tp::test
