#include "core/calibrate/pass_work.h"

#include <algorithm>

namespace tp {
namespace {

bool isAttachment(Use u) {
    return u == Use::ColorAttachment || u == Use::ColorResolve || u == Use::DepthAttachment ||
           u == Use::DepthResolve || u == Use::DepthTest;
}

RasterPath rasterPath(const GraphDecl::Pass& p, const PassWorkInput& in) {
    bool depth = false, msaa = false;
    uint32_t colours = 0;
    for (const PassUse& u : p.uses) {
        if (!isAttachment(u.use)) continue;
        colours += u.use == Use::ColorAttachment ? 1u : 0u;
        depth |= u.use == Use::DepthAttachment || u.use == Use::DepthTest;
        msaa |= in.resourceSamples(u.resource.index) > 1;
    }
    const bool colour = colours > 0;
    if (!colour && !depth) return RasterPath::None;
    if (colours >= kGBufferTargets) return msaa ? RasterPath::GBufferMsaa : RasterPath::GBuffer;
    if (msaa) return colour ? RasterPath::Msaa : RasterPath::DepthOnlyMsaa;
    return colour ? RasterPath::Colour : RasterPath::DepthOnly;
}

// A pass that draws (attachments, or primitives counted) is graphics; one that only reads and
// writes storage or samples is compute; transfers and clears are neither.
PassStage stageOf(const GraphDecl::Pass& p, const PassWork& w) {
    if (w.raster != RasterPath::None || (w.counted && w.counts.inputPrimitives > 0)) return PassStage::Graphics;
    for (const PassUse& u : p.uses)
        if (u.use != Use::TransferSrc && u.use != Use::TransferDst) return PassStage::Compute;
    return PassStage::Other;
}

// An attachment of a counted draw: at most one pixel's samples per fragment.
double attachmentBytes(const PassUse& u, const PassWork& w, const PassWorkInput& in) {
    const double full = double(in.resourceBytes(u.resource.index));
    // A resolve writes the whole area; a draw without a fragment shader (a depth prepass) has no
    // fragments to bound it by.
    const bool resolve = u.use == Use::ColorResolve || u.use == Use::DepthResolve;
    if (!isAttachment(u.use) || resolve || !w.counted || in.framePixels <= 0 || w.counts.fragmentInvocations == 0)
        return full;
    return std::min(full, double(w.counts.fragmentInvocations) * full / in.framePixels);
}

const PassCounts* countsOf(const PassWorkInput& in, const std::string& pass) {
    for (const PassCounts& c : in.counts)
        if (c.pass == pass) return &c;
    return nullptr;
}

// Items of `base` for a pass; < 0 when they cannot be known (fragments without the statistics).
double itemsOf(PassLightWork::Base base, double given, const PassWork& w, const PassWorkInput& in) {
    switch (base) {
    case PassLightWork::Base::Fragments:
        return w.counted ? double(w.counts.fragmentInvocations) : -1.0;
    case PassLightWork::Base::CoveredPixels:
        return in.coveredPixels;
    case PassLightWork::Base::Items:
        return given;
    }
    return -1.0;
}

void joinHow(std::string& into, const std::string& how) {
    if (how.empty()) return;
    into += (into.empty() ? "" : "; ") + how;
}

// Entries of one pass add up (MSAA edge samples beside the pixels); exact only if all are.
void addLightWork(PassWork& w, const PassWorkInput& in) {
    bool any = false, exact = true;
    for (const PassLightWork& l : in.lightWork) {
        if (l.pass != w.pass) continue;
        const double items = itemsOf(l.base, l.items, w, in);
        if (items < 0) continue; // nothing to multiply without the statistics
        w.lightEvaluations += items * l.perItem;
        exact = exact && l.exact;
        any = true;
        joinHow(w.lightHow, l.how);
    }
    w.lightExact = any && exact;
}

void addOpWork(PassWork& w, const PassWorkInput& in) {
    for (const PassOpWork& o : in.opWork) {
        if (o.pass != w.pass) continue;
        const double items = itemsOf(o.base, o.items, w, in);
        if (items < 0) continue;
        auto it = std::find_if(w.ops.begin(), w.ops.end(),
                               [&](const CountedOps& c) { return c.kind == o.kind; });
        if (it == w.ops.end()) it = w.ops.insert(w.ops.end(), CountedOps{o.kind});
        it->count += items * o.perItem;
        it->exact = it->exact && o.exact;
        joinHow(it->how, o.how);
        if (o.kind == PassOpWork::Kind::BytesRead) w.bytesRead += items * o.perItem;
        if (o.kind == PassOpWork::Kind::BytesWritten) w.bytesWritten += items * o.perItem;
    }
}

} // namespace

UseBytes useBytes(Use use, double b) {
    switch (use) {
    case Use::ColorAttachment:
    case Use::ColorResolve:
    case Use::DepthResolve:
    case Use::StorageWrite:
    case Use::TransferDst:
        return {0, b};
    case Use::DepthAttachment:
        return {b, b};
    case Use::DepthTest:
    case Use::Sampled:
    case Use::StorageRead:
    case Use::TransferSrc:
    case Use::IndirectRead:
        return {b, 0};
    }
    return {};
}

std::vector<PassWork> countPassWork(const PassWorkInput& in) {
    std::vector<PassWork> out;
    for (uint32_t index : in.livePasses) {
        const GraphDecl::Pass& p = in.decl->passes().at(index);
        PassWork w;
        w.pass = p.name;
        w.raster = rasterPath(p, in);
        if (const PassCounts* c = countsOf(in, p.name)) {
            w.counted = true;
            w.counts = c->counts;
        }
        for (const PassUse& u : p.uses) {
            const UseBytes b = useBytes(u.use, attachmentBytes(u, w, in));
            w.bytesRead += b.read;
            if (in.decl->resources().at(u.resource.index).isImage) {
                w.imageBytesRead += b.read;
                if (in.resourceSamples && in.resourceSamples(u.resource.index) > 1)
                    w.msaaImageBytesRead += b.read;
            }
            w.bytesWritten += b.written;
        }
        w.stage = stageOf(p, w);
        // Pixels through the raster path: the fragments, or for a draw without a fragment shader
        // (a depth prepass) the pixels with geometry.
        w.rasterPixels = w.counts.fragmentInvocations > 0 ? double(w.counts.fragmentInvocations)
                         : w.counted && w.counts.clippingPrimitives > 0 ? in.coveredPixels : 0.0;
        addLightWork(w, in);
        addOpWork(w, in);
        out.push_back(w);
    }
    return out;
}

} // namespace tp
