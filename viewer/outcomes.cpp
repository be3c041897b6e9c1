// The viewer's side of the workers' outcomes (render_worker.h): what each finished render
// becomes on the screen (Shown), and a shared device's second outcome merged into it.
#include <algorithm>

#include "core/util/clock.h"
#include "viewer/viewer_app.h"

namespace tp::view {

// A finished image as the UI keeps it (its timings join the pipeline's history).
Shown ViewerApp::makeShown(PipelineImage& image, const RenderOutcome& o) {
    Shown s{image.pipeline, o.key,        image.error, nullptr,
            image.buildMs,  nextSerial_++, o.lights,   o.camera,
            image.planned,  image.updateMs, image.display};
    s.framesMs = image.framesMs;
    s.steps = image.steps;
    if (image.error.empty()) {
        history_[image.pipeline].add(image.run.timings, image.buildMs);
        s.run = std::make_shared<const RunResult>(std::move(image.run));
    }
    return s;
}

void ViewerApp::takeOutcome(RenderOutcome& o) {
    if (auto it = submittedAt_.find(o.id); it != submittedAt_.end()) {
        lastLatencyMs_ = msSince(it->second);
        submittedAt_.erase(submittedAt_.begin(), std::next(it)); // and older, replaced ones
    }
    error_ = o.error;
    lastRebuilt_ = o.rebuilt;
    lastRenderMs_ = o.totalMs;
    lastSceneMs_ = o.sceneMs;
    if (o.error.empty()) {
        sceneMemory_ = o.sceneMemory;
        lightCount_ = o.lightCount;
        triangleCount_ = o.triangleCount;
        sceneCamera_ = o.sceneCamera;
        hasSceneCamera_ = true;
        if (state_.cameraFromScene) state_.camera = sceneCamera_;
    }
    for (PipelineImage& image : o.images) {
        if (image.error.empty() && image.partial && !image.planned)
            keepLastCollected(image.run, image.pipeline);
        if (!image.error.empty()) error_ = image.error;
        shown_[image.pipeline] = makeShown(image, o);
    }
}

// A shared view's run holds its timings and view counters only until its second outcome (which
// a moving camera skips): the counters, memory, work and overlays shown meanwhile are the last
// ones read, of an earlier view of the same plan; this view's own counters replace theirs.
void ViewerApp::keepLastCollected(RunResult& run, const std::string& pipeline) const {
    auto it = shown_.find(pipeline);
    if (it == shown_.end() || !it->second.run) return;
    const RunResult& last = *it->second.run;
    const auto fresh = run.stats.counters;
    run.stats = last.stats;
    for (const auto& [name, value] : fresh) {
        auto same = std::find_if(run.stats.counters.begin(), run.stats.counters.end(),
                                 [&](const auto& c) { return c.first == name; });
        if (same != run.stats.counters.end()) same->second = value;
        else run.stats.counters.push_back({name, value});
    }
    run.memory = last.memory;
    run.work = last.work;
    run.efficiency = last.efficiency;
    run.debugImages = last.debugImages;
    run.passes = last.passes;
    run.culledPasses = last.culledPasses;
    run.statisticsCollected = last.statisticsCollected;
    run.statisticsWhy = last.statisticsWhy;
}

// The whole runs of images already shown (a shared device's second outcome): counters,
// memory, and the hdr and depth when asked, as a new image for what reads them.
void ViewerApp::takeCollected(RenderOutcome& o) {
    for (PipelineImage& image : o.images) {
        auto it = shown_.find(image.pipeline);
        if (it == shown_.end() || it->second.key != o.key || !it->second.run) continue;
        if (!image.error.empty()) {
            error_ = image.error;
            continue;
        }
        imageReadbacks_ += image.run.hdr.width > 0 ? 1 : 0;
        it->second.run = std::make_shared<const RunResult>(std::move(image.run));
        it->second.serial = nextSerial_++;
    }
}

void ViewerApp::takeOutcomes() {
    bool taken = false;
    while (std::optional<RenderOutcome> o = worker_->take()) {
        if (o->collected)
            takeCollected(*o);
        else
            takeOutcome(*o);
        taken = true;
    }
    if (std::optional<RenderOutcome> o = referenceWorker_->take()) {
        if (!o->error.empty() && error_.empty()) error_ = o->error;
        for (PipelineImage& image : o->images)
            reference_ = makeShown(image, *o);
        taken = true;
    }
    if (taken) sceneInputsChanged_ = true;
}

} // namespace tp::view
