#include "core/calibrate/efficiency.h"

#include <algorithm>
#include <string>

namespace tp {
namespace {

struct Placer {
    const CeilingRates& rates;
    double spotShare;
    std::vector<std::string>& missing;

    // Base units per second, 0 when the calibration lacks it (recorded once as missing).
    double rate(const std::string& name) const {
        auto it = rates.find(name);
        if (it != rates.end() && it->second > 0) return it->second;
        if (std::find(missing.begin(), missing.end(), name) == missing.end()) missing.push_back(name);
        return 0;
    }
    double ms(double work, double perSecond) const { return perSecond > 0 ? work / perSecond * 1e3 : 0; }

    // An image is read at the faster of the buffer stream and image_read (texel fetches of an
    // image that fits a last-level cache, as one the previous pass wrote may; on lavapipe a path
    // of its own): the stream alone is no upper bound on how fast a pass reads its depth. A
    // multisampled image may also go at image_read_msaa4 (its samples read together: on lavapipe
    // faster a byte than single texels, docs/efficiency.md).
    LimitTime memory(const PassWork& w) const {
        const double msaa = w.msaaImageBytesRead, single = w.imageBytesRead - msaa;
        const double buffers = w.bytesRead - w.imageBytesRead;
        const double singleRate =
            w.imageBytesRead > 0 ? std::max(rate("dram_read"), rate("image_read")) : 0.0;
        const double msaaRate = msaa > 0 ? std::max(singleRate, rate("image_read_msaa4")) : 0.0;
        std::string ceiling = "dram_read";
        if (w.imageBytesRead > 0) ceiling += ", image_read";
        if (msaa > 0) ceiling += ", image_read_msaa4";
        return {"memory", ceiling + " + dram_write",
                ms(buffers, rate("dram_read")) + ms(single, singleRate) + ms(msaa, msaaRate) +
                    ms(w.bytesWritten, rate("dram_write"))};
    }
    // Light evaluations at the stage's light-model ceilings, point and spot in the scene's mix.
    LimitTime lightAlu(const PassWork& w) const {
        const std::string prefix = w.stage == PassStage::Compute ? "light_" : "fragment_light_";
        const double t = ms(w.lightEvaluations * (1 - spotShare), rate(prefix + "point")) +
                         (spotShare > 0 ? ms(w.lightEvaluations * spotShare, rate(prefix + "spot")) : 0.0);
        return {"light_alu", prefix + "point, " + prefix + "spot", t};
    }
    // The ceiling that does no more per pixel than the pass: colour alone or depth alone, at
    // the pass's sample count. A pass that also tests or writes depth, or blends, does more.
    static const char* rasterCeiling(RasterPath r) {
        switch (r) {
        case RasterPath::DepthOnly:
            return "raster_depth";
        case RasterPath::DepthOnlyMsaa:
            return "raster_depth_msaa4";
        case RasterPath::Msaa:
            return "rop_colour_msaa4";
        case RasterPath::GBuffer:
            return "rop_gbuffer";
        case RasterPath::GBufferMsaa:
            return "rop_gbuffer_msaa4";
        case RasterPath::Colour:
        case RasterPath::None:
            break;
        }
        return "rop_colour";
    }
    LimitTime raster(const PassWork& w) const {
        const char* c = rasterCeiling(w.raster);
        return {"raster", c, ms(w.rasterPixels, rate(c))};
    }
    // The materials' fetches at the stage's texture ceiling (bilinear, one mip level: a
    // trilinear or anisotropic fetch costs at least one of them).
    LimitTime texture(const PassWork& w) const {
        const char* c = w.stage == PassStage::Compute ? "texture_fetch" : "fragment_texture_fetch";
        return {"texture", c, ms(w.opCount(PassOpWork::Kind::TextureFetches), rate(c))};
    }
    // Atomics of both kinds, each at its own ceiling (one pass may make both).
    LimitTime atomics(const PassWork& w) const {
        const double global = w.opCount(PassOpWork::Kind::GlobalAtomics),
                     shared = w.opCount(PassOpWork::Kind::SharedAtomics);
        std::string c = global > 0 ? "global_atomic" : "";
        if (shared > 0) c += std::string(c.empty() ? "" : " + ") + "shared_atomic";
        const double t = (global > 0 ? ms(global, rate("global_atomic")) : 0.0) +
                         (shared > 0 ? ms(shared, rate("shared_atomic")) : 0.0);
        return {"atomics", c, t};
    }
    // Every primitive submitted at the rate of triangles that are all culled: the least any
    // triangle costs (those the pass rasterizes cost more; raster and ROPs place them).
    LimitTime triangles(const PassWork& w) const {
        return {"triangles", "tri_culled", ms(double(w.counts.inputPrimitives), rate("tri_culled"))};
    }

    // Every draw command at the rate of indirect draws whose one triangle is culled: the least a
    // draw costs the command processor (a direct draw, or one that rasterizes, costs more).
    LimitTime draws(const PassWork& w) const {
        return {"draws", "draw_culled", ms(w.opCount(PassOpWork::Kind::Draws), rate("draw_culled"))};
    }

    PassEfficiency place(const PassWork& w, double measuredMs) const {
        PassEfficiency e{w.pass, measuredMs};
        // Transfers and clears are not placed: no ceiling measures vkCmdFillBuffer (lavapipe's is
        // a memset, many times its shader stores).
        if (w.stage == PassStage::Other) return e;
        if (w.bytesRead + w.bytesWritten > 0) e.limits.push_back(memory(w));
        if (w.lightEvaluations > 0) e.limits.push_back(lightAlu(w));
        if (w.counted && w.stage == PassStage::Graphics && w.rasterPixels > 0) e.limits.push_back(raster(w));
        if (w.counted && w.counts.inputPrimitives > 0) e.limits.push_back(triangles(w));
        if (w.opCount(PassOpWork::Kind::TextureFetches) > 0) e.limits.push_back(texture(w));
        if (w.opCount(PassOpWork::Kind::Draws) > 0) e.limits.push_back(draws(w));
        if (w.opCount(PassOpWork::Kind::GlobalAtomics) +
                w.opCount(PassOpWork::Kind::SharedAtomics) >
            0)
            e.limits.push_back(atomics(w));
        for (const LimitTime& l : e.limits)
            if (l.ms > e.bound.ms) e.bound = l;
        e.percent = measuredMs > 0 ? e.bound.ms / measuredMs * 100 : 0;
        e.bytes = w.bytesRead + w.bytesWritten;
        if (w.lightEvaluations > 0) roofline(w, e);
        return e;
    }
    // FLOPs of the FMA loop that runs as long as the evaluations do, on the same stage.
    void roofline(const PassWork& w, PassEfficiency& e) const {
        const bool compute = w.stage == PassStage::Compute;
        e.roof = compute ? "fp32_fma" : "fragment_fma";
        const auto roof = rates.find(e.roof); // optional: no roofline point without it
        e.flops = roof == rates.end() ? 0.0 : lightAlu(w).ms * 1e-3 * roof->second;
    }
};

double timingOf(const std::vector<TimingStats>& timings, const std::string& name) {
    for (const TimingStats& t : timings)
        if (t.name == name) return t.medianMs;
    return 0;
}

} // namespace

FrameEfficiency placeFrame(const std::vector<PassWork>& work, const std::vector<TimingStats>& timings,
                           const CeilingRates& rates, double spotShare) {
    FrameEfficiency f;
    Placer placer{rates, std::clamp(spotShare, 0.0, 1.0), f.missingCeilings};
    f.frameMs = timingOf(timings, "frame");
    for (const PassWork& w : work) {
        f.passes.push_back(placer.place(w, timingOf(timings, w.pass)));
        f.boundSumMs += f.passes.back().bound.ms;
    }
    f.percent = f.frameMs > 0 ? f.boundSumMs / f.frameMs * 100 : 0;
    return f;
}

} // namespace tp
