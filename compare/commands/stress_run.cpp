// triptych stress: for each case, one SceneGpu, the reference then every pipeline (one
// frame each: stress measures images, not time), images and difference maps into
// OUT/CASE/, then stress.html and, last, stress.json (a folder without it is unfinished).
#include "compare/commands/stress_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "compare/measure/stress_measure.h"
#include "compare/measure/stress_shadows.h"
#include "compare/report/report_json.h"
#include "compare/report/stress_report.h"
#include "compare/report/svg_plot.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/image/difference.h"
#include "core/image/image_io.h"
#include "core/image/tonemap.h"
#include "core/reference/reference_renderer.h"
#include "core/util/clock.h"
#include "core/util/files.h"

namespace tp::cli {
namespace {

void check(const Status& s) {
    if (!s) throw UsageError(s.error());
}

StressOutcome renderOne(GpuContext& ctx, SceneGpu& scene, const std::string& name,
                        const Scene& cpuScene, const RenderSettings& settings) {
    StressOutcome p;
    p.name = name;
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    Result<RunResult> result = tryRunRenderer(
        ctx, scene, **findRenderer(name), analyzeScene(cpuScene, settings.msaa), settings, once);
    if (result)
        p.run = std::move(*result);
    else
        p.error = result.error();
    return p;
}

void writeImages(const std::string& dir, const std::string& rel, StressOutcome& p, float ev) {
    check(writeExr(dir + "/" + p.name + ".exr", p.run->hdr, ExrPixelType::Float));
    check(writePng(dir + "/" + p.name + ".png", tonemapToDisplay(p.run->hdr, ev)));
    p.files = {rel + "/" + p.name + ".exr", rel + "/" + p.name + ".png"};
}

void writeDifferences(const std::string& dir, const std::string& rel, StressCaseResult& r,
                      const std::vector<ImageRGBA>& diffs) {
    if (!(r.diffScale > 0.0f)) r.diffScale = 1e-6f; // a legend needs a non-zero end
    for (size_t i = 0; i < r.pipelines.size(); ++i) {
        StressOutcome& p = r.pipelines[i];
        if (!p.run || diffs[i].pixelCount() == 0)
            continue; // not measured (e.g. the reference unusable)
        check(writeExr(dir + "/" + p.name + "_diff.exr", diffs[i], ExrPixelType::Float));
        check(writePng(dir + "/" + p.name + "_diff.png", heatMap(diffs[i], r.diffScale, 12)));
        p.files.push_back(rel + "/" + p.name + "_diff.exr");
        p.files.push_back(rel + "/" + p.name + "_diff.png");
    }
}

// A case's inert lights (StressCase::inertLights, the last of the list) must contribute
// exactly nothing: the twin is the same scene with their intensity 0, so the lights, their
// number and order, the culling, the batches and the shader variants are the same and only
// what the inert lights add can differ.
struct InertTwin {
    Scene scene;
    std::unique_ptr<SceneGpu> gpu;
    InertTwin(GpuContext& ctx, const Scene& s, uint32_t inert) : scene(s) {
        for (size_t i = scene.lights.size() - inert; i < scene.lights.size(); ++i)
            scene.lights[i].intensity = 0.0f;
        gpu = std::make_unique<SceneGpu>(ctx, scene);
    }
};

void checkInert(GpuContext& ctx, InertTwin* twin, StressOutcome& p,
                const RenderSettings& settings) {
    if (!twin || !p.run) return;
    StressOutcome t = renderOne(ctx, *twin->gpu, p.name, twin->scene, settings);
    p.inertChecked = true;
    p.inertChanged = t.run ? bitDifferentPixels(p.run->hdr, t.run->hdr) : p.run->hdr.pixelCount();
}

// A pipeline that could not run fails its case with the reason as its only check.
void failUnrun(StressOutcome& p, const std::string& why) {
    p.pass = false;
    p.checks.push_back({"ran", false, 0, 1, why.empty() ? p.error : why});
}

// A shadowed case's exact reference (--reference-shadows rays), its images and its inert-light
// check, beside the maps reference (`r.reference`, which the pipelines are measured against).
void renderRays(GpuContext& ctx, SceneGpu& gpuScene, const Scene& scene, InertTwin* twin,
                StressCaseResult& r, const std::string& dir) {
    const RenderSettings settings = withReferenceShadows(r.settings, kReferenceShadowRays);
    r.shadow.emplace();
    StressOutcome& rays = r.shadow->rays;
    rays = renderOne(ctx, gpuScene, kReferenceRenderer, scene, settings);
    if (!rays.run) return;
    countNonFinite(rays.run->hdr, rays.nanPixels, rays.infPixels);
    checkInert(ctx, twin, rays, settings);
    rays.name = "reference_rays";
    writeImages(dir, r.c->name, rays, r.exposureEv);
    if (!r.reference.run) return;
    const ImageRGBA diff = signedDifference(r.reference.run->hdr, rays.run->hdr);
    const std::string base = "reference_maps_vs_rays_diff";
    check(writeExr(dir + "/" + base + ".exr", diff, ExrPixelType::Float));
    check(writePng(dir + "/" + base + ".png",
                   heatMap(diff, std::max(differencePercentile99(diff), 1e-6f), 12)));
    rays.files.push_back(r.c->name + "/" + base + ".exr");
    rays.files.push_back(r.c->name + "/" + base + ".png");
}

std::string referenceFault(const StressOutcome& ref) {
    if (!ref.run) return "failed: " + ref.error;
    if (ref.nanPixels + ref.infPixels) return "has NaN/Inf pixels";
    return "changes " + std::to_string(ref.inertChanged) +
           " pixels with lights that must contribute nothing";
}

StressCaseResult runCase(GpuContext& ctx, const stress::StressCase& c,
                         const std::vector<std::string>& names, const StressOptions& o) {
    const std::string& out = o.out;
    auto start = std::chrono::steady_clock::now();
    StressCaseResult r;
    r.c = &c;
    r.settings = o.knobs;
    r.settings.width = c.width;
    r.settings.height = c.height;
    r.settings.msaa = c.msaa;
    r.settings.shadows = c.shadows; // none unless the case is about shadows
    r.subPixelBits = ctx.properties.limits.subPixelPrecisionBits;
    const Scene scene = c.build();
    r.lights = scene.lights.size();
    r.triangles = scene.triangleCount();
    const std::string dir = out + "/" + c.name;
    std::filesystem::remove_all(dir);
    ensureDirectory(dir);
    SceneGpu gpuScene(ctx, scene);
    std::unique_ptr<InertTwin> twin;
    if (c.inertLights)
        twin = std::make_unique<InertTwin>(ctx, scene, std::min(c.inertLights, uint32_t(r.lights)));
    // A shadowed case measures the pipelines against the reference on the same shadow maps.
    const bool shadowed = c.shadows.enabled();
    const RenderSettings refSettings =
        shadowed ? withReferenceShadows(r.settings, kReferenceShadowMaps) : r.settings;
    const std::string missing = shadowed ? missingShadowReferences() : "";
    if (missing.empty()) {
        r.reference = renderOne(ctx, gpuScene, kReferenceRenderer, scene, refSettings);
    } else {
        r.reference.name = kReferenceRenderer;
        r.reference.error = missing;
    }
    if (r.reference.run) {
        r.exposureEv = autoExposureEv(r.reference.run->hdr);
        countNonFinite(r.reference.run->hdr, r.reference.nanPixels, r.reference.infPixels);
        writeImages(dir, c.name, r.reference, r.exposureEv);
        checkInert(ctx, twin.get(), r.reference, refSettings);
        if (shadowed) renderRays(ctx, gpuScene, scene, twin.get(), r, dir);
    }
    const bool refUsable = r.reference.run && r.reference.nanPixels + r.reference.infPixels == 0 &&
                           r.reference.inertChanged == 0;
    std::vector<ImageRGBA> diffs;
    for (const std::string& name : names) {
        std::fprintf(stderr, "triptych: stress %s: %s ...\n", c.name.c_str(), name.c_str());
        StressOutcome p = renderOne(ctx, gpuScene, name, scene, r.settings);
        diffs.emplace_back();
        if (!p.run) {
            failUnrun(p, "");
        } else if (!refUsable) {
            failUnrun(p, "the reference " + referenceFault(r.reference));
            if (r.reference.run) writeImages(dir, c.name, p, r.exposureEv); // to see, not measured
        } else {
            checkInert(ctx, twin.get(), p, r.settings);
            writeImages(dir, c.name, p, r.exposureEv);
            measureOutcome(p, r.reference, r, scene);
            diffs.back() = signedDifference(p.run->hdr, r.reference.run->hdr);
            p.diffP99 = differencePercentile99(diffs.back());
            r.diffScale = std::max(r.diffScale, p.diffP99);
        }
        r.pipelines.push_back(std::move(p));
    }
    writeDifferences(dir, c.name, r, diffs);
    r.pass = refUsable;
    for (const StressOutcome& p : r.pipelines)
        r.pass &= p.pass;
    if (r.shadow) {
        measureShadowTechnique(r, scene, gpuScene.shadowPlan());
        r.pass &= r.shadow->pass;
    }
    r.seconds = secondsSince(start);
    return r;
}

void printVerdict(const std::string& name, bool pass, const std::vector<StressCheck>& checks) {
    std::string failed;
    for (const StressCheck& k : checks)
        if (!k.pass)
            failed += (failed.empty() ? "" : "; ") + k.name + " " + formatNumber(k.measured) +
                      " (limit " + formatNumber(k.limit) + ")";
    std::printf("  %-20s %s%s%s\n", name.c_str(), pass ? "pass" : "FAIL",
                failed.empty() ? "" : ": ", failed.c_str());
}

void printCase(const StressCaseResult& r) {
    std::printf("%-26s %s (%.1f s)\n", r.c->name.c_str(), r.pass ? "pass" : "FAIL", r.seconds);
    for (const StressOutcome& p : r.pipelines)
        printVerdict(p.name, p.pass, p.checks);
    if (r.shadow) printVerdict("shadow technique", r.shadow->pass, r.shadow->checks);
}

} // namespace

int runStress(const StressOptions& o) {
    Result<std::vector<const stress::StressCase*>> cases = stress::selectStressCases(o.cases);
    if (!cases) throw UsageError(cases.error());
    checkKnobs(o.knobs.knobs);
    std::vector<std::string> names = selectPipelines(o.pipelines);
    std::unique_ptr<GpuContext> ctx = createContext(o.device);
    for (const stress::StressCase* c : *cases)
        makeSettings({std::to_string(c->width) + "x" + std::to_string(c->height), int(c->msaa)},
                     *ctx);
    ensureDirectory(o.out);
    for (const char* f : {"stress.json", "stress.html"})
        std::filesystem::remove(o.out + "/" + f);
    std::vector<StressCaseResult> results;
    for (const stress::StressCase* c : *cases) {
        results.push_back(runCase(*ctx, *c, names, o));
        printCase(results.back());
    }
    const std::vector<std::string> validation = ctx->validationMessages();
    nlohmann::json report = stressJson(o.commandLine, *ctx, results, validation);
    Result<std::string> html = stressHtml(report, o.out);
    if (!html) throw UsageError(html.error());
    check(writeTextFile(o.out + "/stress.html", *html));
    check(writeTextFile(o.out + "/stress.json",
                        report.dump(2) + "\n")); // last: marks the run complete
    size_t failed = 0;
    for (const StressCaseResult& r : results)
        failed += !r.pass;
    std::fprintf(stderr,
                 "triptych: %zu of %zu cases passed; wrote %s/stress.html and stress.json\n",
                 results.size() - failed, results.size(), o.out.c_str());
    if (int code = validationExit(validation)) return code;
    return failed ? 6 : 0;
}

} // namespace tp::cli
