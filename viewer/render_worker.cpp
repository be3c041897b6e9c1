#include "viewer/render_worker.h"

#include <algorithm>
#include <chrono>

#include "core/cli/scene_input.h"
#include "core/energy/energy_window.h"
#include "core/gpu/barriers.h"
#include "core/gpu/readback.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/runner/device_energy.h"
#include "core/scene/lights.h"
#include "core/util/clock.h"

namespace tp::view {

RenderWorker::RenderWorker(ContextOptions options, std::string label, GpuContext* share,
                           bool showFirst)
    : options_(std::move(options)), label_(std::move(label)), share_(share),
      showFirst_(showFirst || share) {
    thread_ = std::thread([this] { loop(); });
}

RenderWorker::~RenderWorker() {
    stop();
}

std::vector<std::string> RenderWorker::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quit_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    return messages_;
}

void RenderWorker::submit(RenderJob job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        pending_ = std::move(job);
    }
    wake_.notify_all();
}

std::optional<RenderOutcome> RenderWorker::take() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (done_.empty()) return std::nullopt;
    std::optional<RenderOutcome> out = std::move(done_.front());
    done_.pop_front();
    return out;
}

bool RenderWorker::idle() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return !pending_ && !running_ && done_.empty();
}

void RenderWorker::publish(RenderOutcome outcome) {
    std::lock_guard<std::mutex> lock(mutex_);
    done_.push_back(std::move(outcome));
}

void RenderWorker::loop() {
    if (share_) {
        ctx_ = GpuContext::share(*share_, 1);
        energy_ = openDeviceEnergy(*ctx_);
    } else if (Result<std::unique_ptr<GpuContext>> ctx = GpuContext::create(options_)) {
        ctx_ = std::move(*ctx);
        energy_ = openDeviceEnergy(*ctx_);
    } else {
        contextError_ = ctx.error();
    }
    for (;;) {
        RenderJob job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return quit_ || pending_; });
            if (quit_) break;
            job = std::move(*pending_);
            pending_.reset();
            running_ = true;
        }
        RenderOutcome outcome = runJob(job);
        std::optional<RenderOutcome> collected;
        const bool shown = showFirst_ && outcome.error.empty();
        if (shown) {
            publish(outcome); // on the screen now; what the CPU reads of it follows
            collected = collectLater(job, outcome);
        }
        std::lock_guard<std::mutex> lock(mutex_);
        if (!shown) done_.push_back(std::move(outcome));
        if (collected) done_.push_back(std::move(*collected));
        running_ = false;
    }
    // Everything on this device is released here, on its own thread, before its messages are read:
    // first the outcomes nobody took (they hold display images of this context).
    {
        std::lock_guard<std::mutex> lock(mutex_);
        done_.clear();
        pending_.reset();
    }
    displays_.clear();
    sessions_.clear();
    gpuScene_.reset();
    if (ctx_) messages_ = ctx_->validationMessages();
    ctx_.reset();
}

// Loads the scene when its key changed, regenerates the lights when theirs did.
void RenderWorker::prepareScene(const RenderJob& job, RenderOutcome& out) {
    const ViewState& s = job.state;
    auto start = std::chrono::steady_clock::now();
    if (sceneKey(s) != sceneKey_) {
        sessions_.clear(); // they hold the old scene
        gpuScene_.reset();
        scene_.reset();
        sceneKey_.clear();
        lightsKey_.clear();
        cli::SceneOptions plain = s.scene; // the scene's own lights; generated ones follow
        plain.lightCount = 0;
        plain.lightsFile.clear();
        plain.dropSceneLights = false;
        scene_ = std::make_unique<Scene>(cli::loadScene(plain));
        sceneLights_ = scene_->lights;
        sceneCamera_ = scene_->camera;
        gpuScene_ = std::make_unique<SceneGpu>(*ctx_, *scene_);
        sceneKey_ = sceneKey(s);
        out.rebuilt = "scene";
    }
    if (lightsKey(s) != lightsKey_) {
        std::vector<Light> lights = s.scene.dropSceneLights ? std::vector<Light>{} : sceneLights_;
        if (!s.scene.lightsFile.empty()) {
            Result<std::vector<Light>> file = readLightsFile(s.scene.lightsFile);
            if (!file) throw cli::UsageError(file.error());
            lights = std::move(*file);
        } else {
            std::vector<Light> generated =
                generateLights(scene_->bounds, cli::generatorOptions(s.scene));
            lights.insert(lights.end(), generated.begin(), generated.end());
        }
        scene_->lights = std::move(lights);
        gpuScene_->setLights(scene_->lights);
        lightsKey_ = lightsKey(s);
        startLights_ = scene_->lights;
        motionPlan_.reset();
        movedKey_.clear(); // the start lights are uploaded
        if (out.rebuilt.empty()) out.rebuilt = "lights";
    }
    out.sceneMs = out.rebuilt.empty() ? 0.0 : msSince(start);
    moveLights(s);
}

// The lights of the state's frame under --light-motion, as compare's path run moves them
// (core/scene/light_motion.h, seeded by the light seed): the same count, so the sessions
// follow them without a new plan.
void RenderWorker::moveLights(const ViewState& s) {
    const std::string key = motionKey(s);
    if (key == movedKey_) return;
    if (s.lightMotion == "none") {
        scene_->lights = startLights_;
    } else {
        if (!motionPlan_ || motionPlanFor_ != s.lightMotion) {
            Result<LightMotion> motion = parseLightMotion(s.lightMotion);
            if (!motion) throw cli::UsageError(motion.error());
            motion->seed = s.scene.seed;
            motionPlan_ = std::make_unique<LightMotionPlan>(startLights_, *motion, scene_->bounds);
            motionPlanFor_ = s.lightMotion;
        }
        scene_->lights = motionPlan_->at(s.lightFrame);
    }
    gpuScene_->setLights(scene_->lights);
    movedKey_ = key;
}

// One pipeline's image of the job: its kept session follows the view, or a new one is planned
// (first use, or the plan key changed). A Vulkan failure is shown in the viewer, not a crash.
PipelineImage RenderWorker::renderPipeline(const std::string& name, const RenderJob& job,
                                           const RenderSettings& settings,
                                           const RunOptions& options) {
    PipelineImage image;
    image.pipeline = name;
    const auto start = std::chrono::steady_clock::now();
    Planned& p = sessions_[name];
    const std::string key = planKey(job.state, job.debug);
    try {
        if (!p.session || p.key != key) {
            p.session.reset();
            Result<const RendererEntry*> entry = findRenderer(name);
            if (!entry) throw RendererError(entry.error());
            auto session = RendererSession::create(*ctx_, *gpuScene_, **entry,
                                                   analyzeScene(*scene_, settings.msaa), settings);
            if (!session) throw RendererError(session.error());
            p.session = std::move(*session);
            p.key = key;
            image.planned = true;
        }
        const uint32_t replans = p.session->replans();
        RunOptions runOptions = withEnergy(name, job, options);
        std::shared_ptr<DisplayImage> display; // shared: filled in the last frame's batch
        if (share_) {
            display = freeDisplay(p.session->hdrImage().desc);
            runOptions.afterLastFrame = [&display](VkCommandBuffer cmd, const Image& hdr) {
                recordDisplayCopy(cmd, hdr, display->image);
            };
        }
        const auto rendering = std::chrono::steady_clock::now();
        Result<RunResult> run = p.session->render(runOptions);
        image.framesMs = msSince(rendering);
        image.steps = p.session->lastSteps();
        if (run) {
            image.run = std::move(*run);
            lastFrameMs_[name] = frameMedianMs(image.run);
            image.display = std::move(display);
            image.partial = !runOptions.readback;
            if (image.partial && !share_) // on a device of its own: the image to show, alone
                image.run.hdr = readbackColor(*ctx_, p.session->hdrImage());
            image.updateMs = image.run.stats.counter("view_update_ms", 0.0);
        } else {
            image.error = run.error();
        }
        image.planned |= p.session->replans() != replans;
    } catch (const std::exception& e) { // RendererError, GpuError
        image.error = e.what();
        if (image.error.rfind(name, 0) != 0 && image.error.rfind("pipeline ", 0) != 0)
            image.error = name + ": " + image.error;
    }
    if (!image.error.empty()) sessions_.erase(name);
    image.buildMs = msSince(start);
    return image;
}

// The energy counter is read only where the frames can fill its window: on an NVIDIA GPU a read
// takes about 3 ms, two a render, for a window a 2 ms frame never fills (the result said so
// anyway). The last frame of the pipeline tells; the first render reads.
RunOptions RenderWorker::withEnergy(const std::string& pipeline, const RenderJob& job,
                                    RunOptions options) const {
    auto last = lastFrameMs_.find(pipeline);
    if (!options.energy || !options.energy->meter || last == lastFrameMs_.end()) return options;
    const double period = options.energy->meter->updatePeriodMs();
    const double window = last->second * double(job.timedFrames);
    if (window >= kPeriodsPerWindow * period) return options;
    auto skipped = std::make_shared<EnergySource>();
    skipped->why = shortWindowReason(window, kPeriodsPerWindow * period, period) +
                   ": not read in the viewer";
    options.energy = std::move(skipped);
    return options;
}

RunOptions RenderWorker::runOptionsFor(const RenderJob& job) const {
    RunOptions runOptions;
    runOptions.warmupFrames = 0;
    runOptions.timedFrames = job.timedFrames;
    runOptions.energy = energy_;
    runOptions.extendEnergyWindow = false; // a render is not held up to lengthen the window
    runOptions.images = job.images;
    if (job.calibration && job.calibration->device == ctx_->info.name &&
        job.calibration->driver == ctx_->info.driver) // shares the file's lifetime
        runOptions.ceilings = std::shared_ptr<const CeilingRates>(job.calibration, &job.calibration->rates);
    return runOptions;
}

RenderOutcome RenderWorker::runJob(const RenderJob& job) {
    RenderOutcome out;
    out.id = job.id;
    out.key = job.key;
    auto start = std::chrono::steady_clock::now();
    if (!ctx_) {
        out.error = contextError_;
        return out;
    }
    try {
        prepareScene(job, out);
    } catch (
        const std::exception& e) { // cli::UsageError: a scene or lights file that fails to load
        out.error = e.what();
        sceneKey_.clear();
        return out;
    }
    out.sceneCamera = sceneCamera_;
    scene_->camera = job.state.cameraFromScene ? sceneCamera_ : job.state.camera;
    out.lightCount = scene_->lights.size();
    out.lights = std::make_shared<const std::vector<Light>>(scene_->lights);
    out.camera = scene_->camera;
    out.triangleCount = scene_->triangleCount();
    out.sceneMemory = ctx_->ledger.entriesOf("scene");
    RenderSettings settings;
    settings.width = job.state.width;
    settings.height = job.state.height;
    settings.msaa = job.state.msaa;
    settings.debug = job.debug;
    settings.knobs = job.state.knobs;
    settings.manyViews = true; // the next job is likely another view
    settings.passStatistics = job.passStatistics;
    RunOptions runOptions = runOptionsFor(job);
    runOptions.readback = !showFirst_; // the frames only (and the image); collectLater reads the rest
    for (auto it = sessions_.begin(); it != sessions_.end();) // only this job's pipelines stay
        it = std::find(job.pipelines.begin(), job.pipelines.end(), it->first) == job.pipelines.end()
                 ? sessions_.erase(it)
                 : std::next(it);
    bool planned = false;
    for (const std::string& name : job.pipelines) {
        out.images.push_back(renderPipeline(name, job, settings, runOptions));
        planned |= out.images.back().planned;
    }
    if (out.rebuilt.empty()) out.rebuilt = planned ? "renderer" : "view";
    out.totalMs = msSince(start);
    return out;
}

// The rest of a shown view's runs (RendererSession::collect: counters, memory, work, the images
// when the job asked), read once the UI has had kStatsGraceMs to ask for another view: a
// camera in motion gets its views shown without them (the panel keeps the last ones read).
std::optional<RenderOutcome> RenderWorker::collectLater(const RenderJob& job,
                                                        const RenderOutcome& shown) {
    {
        std::unique_lock<std::mutex> lock(mutex_);
        if (wake_.wait_for(lock, std::chrono::milliseconds(kStatsGraceMs),
                           [this] { return quit_ || pending_; }))
            return std::nullopt;
    }
    RenderOutcome out;
    out.id = job.id;
    out.key = job.key;
    out.collected = true;
    const auto start = std::chrono::steady_clock::now();
    RunOptions options = runOptionsFor(job);
    options.hdr = share_ != nullptr; // on a device of its own the shown outcome read it already
    for (const PipelineImage& image : shown.images) {
        auto it = sessions_.find(image.pipeline);
        if (!image.error.empty() || it == sessions_.end() || !it->second.session) continue;
        PipelineImage read = image; // the display, timings and the frames' counters
        try {
            RunResult full = it->second.session->collect(options);
            if (!options.hdr) full.hdr = std::move(read.run.hdr); // the frame's, read to show it
            full.energy = image.run.energy;
            for (const auto& counter : image.run.stats.counters) // the session's view counters
                full.stats.counters.push_back(counter);
            read.run = std::move(full);
        } catch (const std::exception& e) {
            read.error = e.what();
        }
        out.images.push_back(std::move(read));
    }
    out.totalMs = msSince(start);
    return out;
}

// A display image nobody else holds (the UI let go of it), or a new one, of `hdr`'s size and
// format.
std::shared_ptr<DisplayImage> RenderWorker::freeDisplay(const ImageDesc& hdr) {
    std::shared_ptr<DisplayImage> target;
    for (auto it = displays_.begin(); it != displays_.end();) {
        const bool free = it->use_count() == 1;
        const ImageDesc& d = (*it)->image.desc;
        if (free && (d.width != hdr.width || d.height != hdr.height || d.format != hdr.format)) {
            it = displays_.erase(it); // another size or format: not coming back
            continue;
        }
        if (free && !target) target = *it;
        ++it;
    }
    if (!target) {
        ImageDesc d = hdr;
        d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        target = std::make_shared<DisplayImage>();
        target->image = createImage(*ctx_, d, {"viewer", "", "display_copy",
                                               "a renderer's image as the UI shows it"});
        displays_.push_back(target);
    }
    return target;
}

// Fills `dst` from `hdr` (TRANSFER_SRC_OPTIMAL after the frame) and leaves it for the UI's
// compute shader; recorded into the batch of the view's last frame (RunOptions::afterLastFrame).
void RenderWorker::recordDisplayCopy(VkCommandBuffer cmd, const Image& hdr, const Image& dst) {
    imageBarrier(cmd, dst.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0, VK_PIPELINE_STAGE_2_COPY_BIT,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkImageCopy region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstSubresource = region.srcSubresource;
    region.extent = {hdr.desc.width, hdr.desc.height, 1};
    vkCmdCopyImage(cmd, hdr.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    imageBarrier(cmd, dst.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT,
                 VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tp::view
