// What a script writes besides screenshots: `stats` (the viewer's state and numbers, for
// tests) and `bench` (render and UI frame times over a camera orbit, for the closing note).
#include <algorithm>
#include <chrono>

#include "core/energy/energy_json.h"
#include "core/reference/reference_renderer.h"
#include "core/util/files.h"
#include "viewer/live_numbers.h"
#include "viewer/script.h"
#include "viewer/viewer_app.h"

namespace tp::view {
namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

nlohmann::json vec3Json(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

// What the numbers panel's live line shows: frames per second and GPU memory.
void liveJson(const ViewerApp& app, const Shown& s, nlohmann::json& j) {
    if (const TimingHistory* h = app.history(s.pipeline)) {
        const LiveRate r = liveRate(*h);
        j["fps"] = {{"shown", r.shownFps()},
                    {"gpu", r.gpuFps()},
                    {"render_ms_median", r.wallMs},
                    {"gpu_frame_ms_median", r.gpuMs},
                    {"renders", r.renders}};
    }
    const LiveMemory m = liveMemory(app, s);
    j["gpu_memory_bytes"] = {{"pipeline", m.pipeline}, {"scene", m.scene}, {"total", m.total()}};
}

nlohmann::json shownJson(const ViewerApp& app, const Shown* s) {
    if (!s) return nullptr;
    nlohmann::json j;
    j["pipeline"] = s->pipeline;
    j["error"] = s->error;
    j["build_ms"] = s->buildMs;
    j["planned"] = s->planned;
    j["view_update_ms"] = s->updateMs;
    j["camera"] = {{"position", vec3Json(s->camera.position)},
                   {"target", vec3Json(s->camera.target)}};
    if (s->run) {
        j["gpu_frame_ms"] = frameGpuMs(s);
        j["debug_images"] = nlohmann::json::array();
        for (const DebugImage& d : s->run->debugImages)
            j["debug_images"].push_back(d.name);
        for (const auto& [name, value] : s->run->stats.counters)
            j["counters"][name] = value;
        j["energy"] = energyJson(s->run->energy); // of this render's timed frames, or why not
        j["pass_statistics"] = s->run->statisticsCollected ? "on" : "off";
        if (s->run->efficiency) { // with --calibration: what the numbers panel shows
            j["efficiency"]["percent_of_ceiling"] = s->run->efficiency->percent;
            for (const PassEfficiency& p : s->run->efficiency->passes)
                if (!p.limits.empty())
                    j["efficiency"]["passes"][p.pass] = {{"ceiling", p.bound.ceiling}, {"percent", p.percent}};
        }
        liveJson(app, *s, j);
    }
    return j;
}

nlohmann::json pathJson(const ViewerApp& app) {
    const PathPlayer& p = app.path();
    if (!p.loaded()) return nullptr;
    return {{"source", p.source},
            {"frames", p.frames},
            {"frame", p.frame},
            {"playing", p.playing},
            {"loop", p.loop},
            {"moves_camera", !p.views.empty()},
            {"light_motion", app.const_state().lightMotion},
            {"light_frame", app.const_state().lightFrame}};
}

nlohmann::json keptErrorJson(const ViewerApp& app) {
    const std::optional<KeptError>& e = app.keptError();
    if (!e) return nullptr;
    return {{"rmse", e->hdr.rmse},           {"psnr", e->hdr.psnr},
            {"max_abs", e->hdr.maxAbs},      {"display_psnr", e->display.psnr},
            {"stale", app.keptErrorStale()}, {"view", e->view}};
}

} // namespace

void ScriptRunner::writeStats(ViewerApp& app, const std::string& file) const {
    const ViewState& s = app.state();
    const Composite& c = app.scene();
    nlohmann::json j;
    j["schema"] = "triptych.view-stats/1";
    j["device"] = app.deviceName();
    j["pipeline_a"] = shownJson(app, app.shownA());
    j["pipeline_b"] = shownJson(app, app.shownB());
    j["path"] = pathJson(app);
    j["mode"] = s.mode == DisplayMode::Split        ? "split"
                : s.mode == DisplayMode::Difference ? "difference"
                                                    : "overlay";
    j["split"] = s.split;
    j["split_column"] = dividerColumn(s.split, c.width ? c.width : s.width);
    j["flip"] = s.flip;
    j["scene_area"] = {c.width, c.height};
    j["difference_scale"] = c.diffScale;
    j["error"] = app.lastError();
    j["reference_stale"] = app.referenceStale();
    j["last_render_ms"] = app.lastRenderMs();
    j["shares_device"] = app.sharesDevice();
    j["image_readbacks"] = app.imageReadbacks();
    if (const auto& e = app.errorVsReference(); e)
        j["a_vs_reference"] = {{"rmse", e->rmse}, {"psnr", e->psnr}, {"max_abs", e->maxAbs}};
    // Kept after the view moves on, with "stale" and the view it is of (what the panel shows).
    j["a_vs_reference_kept"] = keptErrorJson(app);
    const Inspection& i = app.inspection();
    if (i.valid)
        j["inspection"] = {{"x", i.x},
                           {"y", i.y},
                           {"a", {i.a[0], i.a[1], i.a[2]}},
                           {"b", {i.b[0], i.b[1], i.b[2]}},
                           {"surface", i.surface},
                           {"lights", i.lights}};
    const Camera& cam = app.state().camera;
    j["camera"] = {{"position", vec3Json(cam.position)}, {"target", vec3Json(cam.target)}};
    if (Status st = writeTextFile(file, j.dump(2) + "\n"); !st) fail(*current_, st.error());
}

bool ScriptRunner::benchStep(ViewerApp& app) {
    if (benchRecordDue_) {
        benchRenderMs_.push_back(app.lastRenderMs());
        benchLatencyMs_.push_back(app.lastViewLatencyMs());
        benchGpuMs_.push_back(frameGpuMs(app.shownA()));
        if (const Shown* a = app.shownA()) {
            benchUpdateMs_.push_back(a->updateMs);
            benchFramesMs_.push_back(a->framesMs);
            benchSteps_["follow"].push_back(a->steps.followMs);
            benchSteps_["frames"].push_back(a->steps.framesMs);
            benchSteps_["energy_reads"].push_back(a->steps.energyMs);
            benchSteps_["overflow_check"].push_back(a->steps.overflowMs);
            benchSteps_["collect"].push_back(a->steps.collectMs);
            benchPlanned_ += a->planned ? 1 : 0;
        }
        benchRecordDue_ = false;
    }
    if (benchLeft_ > 0) {
        app.orbitCamera(360.0f / float(benchTotal_), 0.0f);
        --benchLeft_;
        benchRecordDue_ = true;
        return true;
    }
    const ViewState& s = app.state();
    nlohmann::json j;
    j["schema"] = "triptych.view-bench/1";
    j["device"] = app.deviceName();
    j["pipeline"] = s.pipelineA;
    j["resolution"] = std::to_string(s.width) + "x" + std::to_string(s.height);
    j["msaa"] = s.msaa;
    j["renders"] = benchRenderMs_.size();
    j["what"] =
        "each render: a camera step, the kept renderer following the view (or planned again: "
        "'planned' counts those), its frame on the GPU, and the image made showable: copied "
        "where the UI composes it (shares_device) or read back; the UI frames draw the panels "
        "and the scene area meanwhile";
    j["shares_device"] = app.sharesDevice();
    j["planned"] = benchPlanned_;
    j["view_update_ms"] = benchUpdateMs_;
    j["view_update_ms_median"] = median(benchUpdateMs_);
    j["render_ms"] = benchRenderMs_;
    j["render_ms_median"] = median(benchRenderMs_);
    j["renders_per_second"] = median(benchRenderMs_) > 0 ? 1000.0 / median(benchRenderMs_) : 0.0;
    j["gpu_frame_ms"] = benchGpuMs_;
    j["gpu_frame_ms_median"] = median(benchGpuMs_);
    j["overhead_ms_median"] = median(benchRenderMs_) - median(benchGpuMs_);
    j["session_render_ms_median"] = median(benchFramesMs_); // update, frames, what it read
    for (const auto& [step, ms] : benchSteps_) // RendererSession::Steps
        j["session_steps_ms_median"][step] = median(ms);
    j["view_latency_ms"] = benchLatencyMs_;
    j["view_latency_ms_median"] = median(benchLatencyMs_);
    j["ui_frames"] = benchUiMs_.size();
    j["ui_frame_ms_median"] = median(benchUiMs_);
    j["ui_frames_per_second"] = median(benchUiMs_) > 0 ? 1000.0 / median(benchUiMs_) : 0.0;
    if (Status st = writeTextFile(benchFile_, j.dump(2) + "\n"); !st) fail(*current_, st.error());
    return false;
}

} // namespace tp::view
