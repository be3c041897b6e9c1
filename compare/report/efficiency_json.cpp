#include "compare/report/efficiency_json.h"

namespace tp::cli {
namespace {

const char* stageName(PassStage s) {
    return s == PassStage::Compute ? "compute" : s == PassStage::Graphics ? "graphics" : "other";
}

const char* rasterName(RasterPath r) {
    switch (r) {
    case RasterPath::DepthOnly: return "depth_only";
    case RasterPath::Colour: return "colour";
    case RasterPath::Msaa: return "msaa";
    case RasterPath::DepthOnlyMsaa:
        return "depth_only_msaa";
    case RasterPath::GBuffer: return "gbuffer";
    case RasterPath::GBufferMsaa: return "gbuffer_msaa";
    case RasterPath::None: break;
    }
    return "none";
}

const char* opName(PassOpWork::Kind k) {
    switch (k) {
    case PassOpWork::Kind::TextureFetches:
        return "texture_fetches";
    case PassOpWork::Kind::GlobalAtomics:
        return "global_atomics";
    case PassOpWork::Kind::SharedAtomics:
        return "shared_atomics";
    case PassOpWork::Kind::TileTests:
        return "light_tile_tests";
    case PassOpWork::Kind::Triangles:
        return "triangles_rasterized";
    case PassOpWork::Kind::BytesRead:
        return "untracked_bytes_read"; // beside bytes_read, which includes them
    case PassOpWork::Kind::BytesWritten:
        return "untracked_bytes_written";
    case PassOpWork::Kind::Draws:
        return "draws";
    }
    return "ops";
}

nlohmann::json limitJson(const LimitTime& l) { return {{"limit", l.limit}, {"ceiling", l.ceiling}, {"ms", l.ms}}; }

} // namespace

nlohmann::json passWorkJson(const std::vector<PassWork>& work) {
    nlohmann::json out = nlohmann::json::array();
    for (const PassWork& w : work) {
        nlohmann::json j = {{"pass", w.pass},
                            {"stage", stageName(w.stage)},
                            {"raster", rasterName(w.raster)},
                            {"bytes_read", w.bytesRead},
                            {"bytes_written", w.bytesWritten},
                            {"light_evaluations", w.lightEvaluations}};
        if (!w.lightHow.empty()) {
            j["light_evaluations_exact"] = w.lightExact;
            j["light_evaluations_how"] = w.lightHow;
        }
        for (const CountedOps& o : w.ops) { // e.g. texture_fetches, texture_fetches_exact, _how
            const std::string name = opName(o.kind);
            j[name] = o.count;
            j[name + "_exact"] = o.exact;
            j[name + "_how"] = o.how;
        }
        if (w.counted)
            j["pipeline_statistics"] = {{"input_primitives", w.counts.inputPrimitives},
                                        {"clipping_invocations", w.counts.clippingInvocations},
                                        {"clipping_primitives", w.counts.clippingPrimitives},
                                        {"fragment_invocations", w.counts.fragmentInvocations}};
        out.push_back(j);
    }
    return out;
}

nlohmann::json efficiencyJson(const FrameEfficiency& f) {
    nlohmann::json passes = nlohmann::json::array();
    for (const PassEfficiency& p : f.passes) {
        nlohmann::json limits = nlohmann::json::array();
        for (const LimitTime& l : p.limits)
            limits.push_back(limitJson(l));
        nlohmann::json j = {{"pass", p.pass},
                            {"measured_ms", p.measuredMs},
                            {"bound", p.limits.empty() ? nlohmann::json(nullptr) : limitJson(p.bound)},
                            {"percent_of_ceiling", p.percent},
                            {"limits", limits}};
        if (p.flops > 0)
            j["roofline"] = {{"flops", p.flops},
                             {"bytes", p.bytes},
                             {"roof", p.roof},
                             {"intensity_flops_per_byte", p.bytes > 0 ? p.flops / p.bytes : 0.0},
                             {"achieved_gflops", p.measuredMs > 0 ? p.flops / (p.measuredMs * 1e-3) / 1e9 : 0.0}};
        passes.push_back(j);
    }
    return {{"frame_ms", f.frameMs},
            {"passes_at_ceiling_ms", f.boundSumMs},
            {"percent_of_ceiling", f.percent},
            {"missing_ceilings", f.missingCeilings},
            {"passes", passes}};
}

} // namespace tp::cli
