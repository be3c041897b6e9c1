#include "multipass_forward/light_count.h"

#include <cstring>

#include "core/calibrate/material_fetches.h"
#include "core/gpu/context.h"
#include "core/gpuscene/scene_gpu.h"
#include "multipass_forward/multipass_shared.h"

namespace tp::mp {
namespace {

constexpr uint64_t kBytes = TP_MP_LIT_SLOTS * 4;

// The sum of a buffer's 32-bit words (a count spread over slots).
double sumOfWords(const std::vector<uint8_t>& bytes) {
    double sum = 0;
    for (size_t i = 0; i + 4 <= bytes.size(); i += 4) {
        uint32_t v;
        std::memcpy(&v, bytes.data() + i, 4);
        sum += v;
    }
    return sum;
}

} // namespace

LightCount::LightCount(GpuContext& ctx, const SceneGpu& scene, bool passStatistics)
    : ctx_(ctx), scene_(scene), enabled_(passStatistics && ctx.reducesFragmentsBySubgroup()) {}

LightCount::~LightCount() {
    if (layout_) vkDestroyPipelineLayout(ctx_.device, layout_, nullptr);
    destroyPassSet(ctx_, set_);
}

void LightCount::plan(FrameGraph& graph, std::vector<PassUse>& lightPassUses) {
    if (!enabled_) return;
    buffer_ = graph.createBuffer("light_pass_lit", kBytes,
                                 "the light passes' fragments that evaluated their light "
                                 "(counted on a GPU with pass statistics)");
    graph.addPass("light_pass_lit_clear", {{buffer_, Use::TransferDst}}, [this](PassContext& pc) {
        vkCmdFillBuffer(pc.cmd, pc.buffer(buffer_).buffer, 0, kBytes, 0u);
    });
    lightPassUses.push_back({buffer_, Use::StorageWrite, TP_MP_BINDING_LIT});
    graph.watchAfterFrame(buffer_, 0, kBytes); // collect() reads it
}

PassEnv LightCount::prepare(FrameGraph& graph, const PassEnv& env,
                            VkDescriptorSetLayout shadowSet) {
    if (!buffer_.valid()) return env;
    set_ = graph.createPassSet("light_passes");
    layout_ = scene_.createPipelineLayout(set_.layout, shadowSet);
    PassEnv counting = env;
    counting.layout = layout_;
    return counting;
}

void LightCount::collect(FrameGraph& graph) {
    if (buffer_.valid()) fragments_ = sumOfWords(graph.watched(buffer_));
}

void LightCount::addWork(RendererStats& s, bool hasLights) const {
    using Base = PassLightWork::Base;
    if (fragments_ < 0) {
        if (hasLights)
            s.leftOut.push_back({"light_passes' light evaluations and texture fetches",
                                 enabled_ ? "no frame has run"
                                          : "a 2x2 quad beyond the light's range skips both, "
                                            "and they are counted only on a GPU with pass "
                                            "statistics"});
        return;
    }
    PassLightWork lit{"light_passes", Base::Items, 1.0, true,
                      "one light per fragment of a 2x2 quad the light reaches (counted)"};
    lit.items = fragments_;
    s.lightWork.push_back(lit);
    PassOpWork fetches = materialFetchWork(scene_, "light_passes",
                                           {DrawFilter::Opaque, DrawFilter::Mask}, Base::Items);
    fetches.items = fragments_;
    fetches.how = "the fewest textures of the draws' materials, per fragment that evaluated its "
                  "light (counted)";
    s.opWork.push_back(fetches);
}

} // namespace tp::mp
