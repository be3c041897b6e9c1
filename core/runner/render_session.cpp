#include "core/runner/render_session.h"

#include <algorithm>
#include <chrono>

#include "core/gpu/context.h"
#include "core/gpu/pass_statistics.h"
#include "core/gpu/profiler.h"
#include "core/gpu/vk_check.h"
#include "core/gpuscene/scene_gpu.h"
#include "core/runner/frame_steps.h"
#include "core/util/clock.h"

namespace tp {
namespace {

constexpr uint32_t kMaxTimedScopes = 64;
// Replans for one view's overflow: a renderer's hint at least doubles what it met, so a few
// cover any growth; past them the drops stay counted in its statistics.
constexpr uint32_t kMaxGrowths = 4;

bool sameConstants(const std::vector<SpecConstant>& a, const std::vector<SpecConstant>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].id != b[i].id || a[i].value != b[i].value) return false;
    return true;
}

} // namespace

RendererSession::RendererSession(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                                 const SceneFeatures& features, const RenderSettings& settings)
    : ctx_(ctx), scene_(scene), entry_(entry), features_(features), settings_(settings) {}

RendererSession::~RendererSession() {
    if (cmd_) ctx_.freeCommandBuffer(cmd_);
    if (afterCmd_) ctx_.freeCommandBuffer(afterCmd_);
}

const std::string& RendererSession::name() const {
    return entry_.name;
}

Result<std::unique_ptr<RendererSession>>
RendererSession::create(GpuContext& ctx, SceneGpu& scene, const RendererEntry& entry,
                        const SceneFeatures& features, const RenderSettings& settings) {
    std::unique_ptr<RendererSession> session(
        new RendererSession(ctx, scene, entry, features, settings));
    if (Status s = session->plan(); !s) return Error{s.error()};
    return session;
}

// Plans, prepares and records for the scene's current view; the previous plan (if any) is
// released first, so a replan never holds two plans' memory.
Status RendererSession::plan() {
    planned_.graph.reset();
    planned_.renderer.reset();
    Result<PlannedRenderer> planned = planRenderer(ctx_, scene_, entry_, features_, settings_);
    if (!planned) return Error{planned.error()};
    planned_ = std::move(*planned);
    if (Status s = detail::pipelineStep(entry_, [&] { planned_.renderer->prepare(*planned_.graph); });
        !s) {
        planned_.graph.reset(); // half prepared: never followed or recorded
        planned_.renderer.reset();
        return s;
    }
    lightCount_ = scene_.lightCount();
    sceneConstants_ = scene_.specConstants(AlphaMode::Opaque);
    // Query pools per plan: a new graph may have other passes (the profiler keeps their names);
    // an update in place records the same passes again into the same pools.
    profiler_ = std::make_unique<GpuProfiler>(ctx_, kMaxTimedScopes);
    statistics_ = settings_.passStatistics ? std::make_unique<PassStatistics>(ctx_, kMaxTimedScopes)
                                           : nullptr; // --pass-statistics off
    return record();
}

Status RendererSession::record() {
    if (!cmd_) cmd_ = ctx_.allocateCommandBuffer();
    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    Status s = detail::pipelineStep(
        entry_, [&] { detail::recordFrame(cmd_, *planned_.graph, *profiler_, statistics_.get()); });
    generation_ = scene_.viewGeneration();
    recorded_ = bool(s);
    return s;
}

// The renderer follows the new view in place where it can; otherwise it is planned again.
Status RendererSession::follow(double& updateMs) {
    const auto start = std::chrono::steady_clock::now();
    bool updated = false;
    if (planned_.renderer && scene_.lightCount() == lightCount_ &&
        sameConstants(scene_.specConstants(AlphaMode::Opaque), sceneConstants_)) {
        Status s = detail::pipelineStep(
            entry_, [&] { updated = planned_.renderer->updateView(*planned_.graph); });
        if (!s) return s;
    }
    Status s = updated ? record() : plan();
    ++(updated ? updates_ : replans_);
    updateMs = msSince(start);
    return s;
}

// RunOptions::afterLastFrame for the plan's hdr as it is now (a replan makes another image).
VkCommandBuffer RendererSession::recordAfter(const RunOptions& options) {
    if (!options.afterLastFrame) return VK_NULL_HANDLE;
    if (!afterCmd_) afterCmd_ = ctx_.allocateCommandBuffer();
    VK_CHECK(vkResetCommandBuffer(afterCmd_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO}; // may go twice
    VK_CHECK(vkBeginCommandBuffer(afterCmd_, &begin));
    options.afterLastFrame(afterCmd_, hdrImage());
    VK_CHECK(vkEndCommandBuffer(afterCmd_));
    return afterCmd_;
}

Result<RunResult> RendererSession::render(const RunOptions& options) {
    auto mark = std::chrono::steady_clock::now();
    auto lap = [&mark](double& ms) { ms += msSince(mark), mark = std::chrono::steady_clock::now(); };
    steps_ = {};
    scene_.setView(settings_.width, settings_.height, settings_.msaa);
    planSceneShadows(ctx_, scene_, settings_.shadows);
    double updateMs = -1;
    // A view change, or a plan or recording that failed last time (tried again).
    if (scene_.viewGeneration() != generation_ || !planned_.renderer || !recorded_)
        if (Status s = follow(updateMs); !s) return Error{s.error()};
    lap(steps_.followMs);
    // Frames until no capacity sized from measured needs overflowed (contract step 7): each
    // overflow plans again with the needs measured, so this ends once they fit. Its time is the
    // view's update time (a replan for this view), its count a replan. No frame: nothing to read.
    const bool framed = options.warmupFrames + options.timedFrames > 0;
    uint32_t warmup = 0;
    FrameEnergy energy;
    for (uint32_t grown = 0;; ++grown) {
        profiler_->discardSamples();
        warmup = detail::submitFrames(ctx_, cmd_, *profiler_, options, energy, recordAfter(options));
        lap(steps_.framesMs);
        steps_.energyMs += energy.readMs;
        const bool overflowed = framed && grown < kMaxGrowths &&
                                planned_.renderer->overflowed(*planned_.graph);
        lap(steps_.overflowMs);
        if (!overflowed) break;
        const auto start = std::chrono::steady_clock::now();
        for (const auto& [name, need] : planned_.renderer->capacityHints())
            settings_.capacities[name] = std::max(settings_.capacities[name], need);
        if (Status s = plan(); !s) return Error{s.error()};
        ++replans_;
        updateMs = std::max(0.0, updateMs) + msSince(start);
    }
    RunResult result = detail::collectResult(ctx_, scene_, entry_, settings_, planned_, *profiler_,
                                             statistics_.get(), options);
    lap(steps_.collectMs);
    result.energy = std::move(energy);
    // more warm-up frames than asked on a GPU: kGpuWarmupMs
    result.stats.counters.push_back({"warmup_frames", double(warmup)});
    if (updates_ + replans_ > 0) {
        result.stats.counters.push_back({"view_update_ms", std::max(0.0, updateMs)});
        result.stats.counters.push_back({"view_updates", double(updates_)});
        result.stats.counters.push_back({"view_replans", double(replans_)});
    }
    return result;
}

const Image& RendererSession::hdrImage() const {
    return planned_.graph->image(planned_.hdr);
}

RunResult RendererSession::collect(const RunOptions& options) {
    return detail::collectResult(ctx_, scene_, entry_, settings_, planned_, *profiler_,
                                 statistics_.get(), options);
}

} // namespace tp
