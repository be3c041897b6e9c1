#include "compare/measure/path_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/camera/camera_file.h"
#include "core/cli/cli_common.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/image/tonemap.h"
#include "core/reference/reference_renderer.h"
#include "core/runner/render_session.h"
#include "core/util/clock.h"

namespace tp::cli {
namespace {

struct Sessions {
    std::unique_ptr<RendererSession> reference;
    std::vector<std::unique_ptr<RendererSession>> pipelines; // null where planning failed
};

std::unique_ptr<RendererSession> plan(const PathRunSetup& s, const std::string& name,
                                      std::string& error) {
    Result<const RendererEntry*> entry = findRenderer(name);
    if (!entry) {
        error = entry.error();
        return nullptr;
    }
    RenderSettings settings = s.settings;
    settings.manyViews = true;
    Result<std::unique_ptr<RendererSession>> session =
        RendererSession::create(s.ctx, s.gpuScene, **entry, s.features, settings);
    if (!session) {
        error = session.error();
        return nullptr;
    }
    return std::move(*session);
}

// One progress line per tenth of the path (and the last view), so a long path shows it moves.
void progress(const std::string& what, uint32_t v, uint32_t views) {
    const uint32_t step = std::max(1u, views / 10);
    if ((v + 1) % step == 0 || v + 1 == views)
        std::fprintf(stderr, "triptych: path %s: view %u/%u\n", what.c_str(), v + 1, views);
}

// Pass 1 for one pipeline: the views back to back; nothing but the view update between frames.
void timeSeries(const PathRunSetup& s, const PathInput& in, RendererSession& session,
                PathSeries& series) {
    const uint32_t views = uint32_t(in.views.size());
    uint32_t updates = 0, replans = 0; // from view 1 on (view 0: where it was planned)
    for (uint32_t v = 0; v < views; ++v) {
        if (v == 1) updates = session.updates(), replans = session.replans();
        applyPathView(s.scene, s.gpuScene, in, v);
        RunOptions ro;
        ro.warmupFrames = v == 0 ? uint32_t(s.warmup) : 0;
        ro.timedFrames = uint32_t(s.frames);
        ro.readback = false;
        Result<RunResult> run = session.render(ro);
        if (!run) {
            series.error = run.error();
            return;
        }
        series.frameMs.push_back(frameMedianMs(*run));
        // View 0 is where the session was planned; following it again from where the previous
        // pipeline left the scene is the harness's cost, not the path's.
        series.updateMs.push_back(v == 0 ? 0.0 : run->stats.counter("view_update_ms", 0.0));
        progress("timing " + series.name, v, views);
    }
    series.updates = session.updates() - (views > 1 ? updates : session.updates());
    series.replans = session.replans() - (views > 1 ? replans : session.replans());
}

// Pass 2: per view, the reference (reused where nothing moved) and every pipeline's error.
void imagePass(const PathRunSetup& s, const PathInput& in, Sessions& sessions, PathRecord& rec) {
    RunOptions once;
    once.warmupFrames = 0;
    once.timedFrames = 1;
    ImageRGBA reference, refDisplay;
    uint64_t referenceGeneration = ~0ull;
    MetricsOptions hdrOptions;
    for (uint32_t v = 0; v < in.views.size(); ++v) {
        applyPathView(s.scene, s.gpuScene, in, v);
        s.gpuScene.setView(s.settings.width, s.settings.height, s.settings.msaa);
        planSceneShadows(s.ctx, s.gpuScene, s.settings.shadows);
        if (s.gpuScene.viewGeneration() != referenceGeneration) {
            const auto start = std::chrono::steady_clock::now();
            Result<RunResult> ref = sessions.reference->render(once);
            if (!ref) throw UsageError("the reference failed at view " + std::to_string(v) +
                                       ": " + ref.error());
            reference = std::move(ref->hdr);
            referenceGeneration = s.gpuScene.viewGeneration();
            ++rec.referenceRenders;
            rec.referenceMs += msSince(start);
            if (v == 0) rec.exposureEv = parseExposure(s.exposure, reference);
            hdrOptions.psnrPeak = brightestFiniteChannel(reference);
            refDisplay = tonemapToDisplay(reference, rec.exposureEv);
        } else {
            ++rec.referenceReused;
        }
        for (size_t p = 0; p < sessions.pipelines.size(); ++p) {
            PathSeries& series = rec.pipelines[p];
            if (!series.error.empty() || !sessions.pipelines[p]) continue;
            Result<RunResult> run = sessions.pipelines[p]->render(once);
            if (!run) {
                series.error = run.error();
                continue;
            }
            series.hdr.push_back(computeError(run->hdr, reference, hdrOptions));
            series.displayPsnr.push_back(
                computeError(tonemapToDisplay(run->hdr, rec.exposureEv), refDisplay).psnr);
        }
        progress("images", v, uint32_t(in.views.size()));
    }
}

uint32_t worstView(const PathRecord& rec) {
    uint32_t worst = 0;
    double largest = -1;
    for (const PathSeries& s : rec.pipelines)
        for (size_t v = 0; v < s.hdr.size(); ++v)
            if (s.hdr[v].rmse > largest) largest = s.hdr[v].rmse, worst = uint32_t(v);
    return worst;
}

// The pipelines that ran the whole path, fastest first at view v.
std::vector<const PathSeries*> ranking(const PathRecord& rec, uint32_t v) {
    std::vector<const PathSeries*> ranked;
    for (const PathSeries& s : rec.pipelines)
        if (s.frameMs.size() == rec.input.views.size()) ranked.push_back(&s);
    std::stable_sort(ranked.begin(), ranked.end(), [&](const PathSeries* a, const PathSeries* b) {
        return a->frameMs[v] < b->frameMs[v];
    });
    return ranked;
}

// A flip: some pair of pipelines is in the other order than at the last kept ranking, and
// the one now ahead is faster by more than kRankMargin (closer times are a tie, not a flip).
std::vector<PathRecord::Flip> rankFlips(const PathRecord& rec) {
    std::vector<PathRecord::Flip> flips;
    if (rec.input.views.size() < 2) return flips;
    std::vector<const PathSeries*> kept = ranking(rec, 0);
    auto names = [](const std::vector<const PathSeries*>& r) {
        std::vector<std::string> n;
        for (const PathSeries* s : r)
            n.push_back(s->name);
        return n;
    };
    for (uint32_t v = 1; v < rec.input.views.size(); ++v) {
        bool flipped = false;
        for (size_t i = 0; i < kept.size() && !flipped; ++i)
            for (size_t k = i + 1; k < kept.size() && !flipped; ++k) {
                const double ahead = kept[i]->frameMs[v], behind = kept[k]->frameMs[v];
                flipped = behind < ahead * (1.0 - kRankMargin);
            }
        if (!flipped) continue;
        std::vector<const PathSeries*> now = ranking(rec, v);
        flips.push_back({v, names(kept), names(now)});
        kept = now;
    }
    return flips;
}

} // namespace

void applyPathView(Scene& scene, SceneGpu& gpuScene, const PathInput& input, uint32_t v) {
    scene.camera = input.views.at(v);
    if (input.lightsAt) {
        scene.lights = input.lightsAt(v);
        gpuScene.setLights(scene.lights);
    }
}

PathRecord runPath(const PathRunSetup& s, const PathInput& input) {
    PathRecord rec;
    rec.input = input;
    applyPathView(s.scene, s.gpuScene, input, 0);
    Sessions sessions;
    std::string error;
    sessions.reference = plan(s, kReferenceRenderer, error);
    if (!sessions.reference) throw UsageError("the reference failed, nothing to compare against: " + error);
    for (const std::string& name : s.pipelines) {
        PathSeries series;
        series.name = name;
        sessions.pipelines.push_back(plan(s, name, series.error));
        rec.pipelines.push_back(std::move(series));
    }
    std::fprintf(stderr, "triptych: path %s: %zu views, lights %s\n", input.source.c_str(),
                 input.views.size(), input.lightMotion.c_str());
    for (size_t p = 0; p < sessions.pipelines.size(); ++p)
        if (sessions.pipelines[p]) timeSeries(s, input, *sessions.pipelines[p], rec.pipelines[p]);
    imagePass(s, input, sessions, rec); // its updates and replans are not the path's
    rec.worstView = worstView(rec);
    rec.rankFlips = rankFlips(rec);
    return rec;
}

PathSeries timePath(const PathRunSetup& s, const PathInput& input, const std::string& pipeline) {
    PathSeries series;
    series.name = pipeline;
    applyPathView(s.scene, s.gpuScene, input, 0);
    std::unique_ptr<RendererSession> session = plan(s, pipeline, series.error);
    if (session) timeSeries(s, input, *session, series);
    return series;
}

nlohmann::json percentilesJson(std::vector<double> values) {
    values.erase(std::remove_if(values.begin(), values.end(),
                                [](double v) { return !std::isfinite(v); }),
                 values.end());
    if (values.empty()) return nullptr;
    std::sort(values.begin(), values.end());
    auto rank = [&](double q) { // nearest rank
        size_t i = size_t(std::ceil(q * double(values.size())));
        return values[std::min(values.size() - 1, i > 0 ? i - 1 : 0)];
    };
    // The median as every timing of the project states it (summarize: the middle two averaged).
    return {{"median", summarize("", values).medianMs},
            {"p95", rank(0.95)},
            {"p99", rank(0.99)},
            {"max", values.back()}};
}

nlohmann::json seriesJson(const PathSeries& s) {
    nlohmann::json p;
    p["name"] = s.name;
    p["error"] = s.error;
    p["frame_ms"] = s.frameMs;
    p["view_update_ms"] = s.updateMs;
    std::vector<double> rmse, total;
    for (const ErrorReport& e : s.hdr)
        rmse.push_back(e.rmse);
    for (size_t v = 0; v < s.frameMs.size() && v < s.updateMs.size(); ++v)
        total.push_back(s.frameMs[v] + s.updateMs[v]);
    p["rmse_hdr"] = rmse;
    p["psnr_display"] = s.displayPsnr;
    p["updates"] = s.updates;
    p["replans"] = s.replans;
    p["summary"] = {{"frame_ms", percentilesJson(s.frameMs)},
                    {"view_ms", percentilesJson(total)},
                    {"view_update_ms", percentilesJson(s.updateMs)},
                    {"rmse_hdr", percentilesJson(rmse)}};
    return p;
}

nlohmann::json pathJson(const PathRecord& rec) {
    nlohmann::json j;
    j["source"] = rec.input.source;
    j["views"] = rec.input.views.size();
    j["light_motion"] = rec.input.lightMotion;
    j["worst_view"] = rec.worstView;
    j["worst_view_camera"] = cameraToJson(rec.input.views.at(rec.worstView));
    j["exposure_ev"] = rec.exposureEv;
    j["reference"] = {{"renders", rec.referenceRenders},
                      {"reused", rec.referenceReused},
                      {"wall_ms", rec.referenceMs}};
    j["timing"] = "frame_ms: per view, the median GPU frame over --frames frames, the views "
                  "rendered back to back after one warm-up; view_update_ms: the CPU time to "
                  "follow the view (updateView and recording, or a replan)";
    j["rank_margin"] = kRankMargin;
    j["rank_flips"] = nlohmann::json::array();
    for (const PathRecord::Flip& f : rec.rankFlips)
        j["rank_flips"].push_back({{"view", f.view}, {"before", f.before}, {"after", f.after}});
    j["pipelines"] = nlohmann::json::array();
    for (const PathSeries& s : rec.pipelines)
        j["pipelines"].push_back(seriesJson(s));
    return j;
}

} // namespace tp::cli
