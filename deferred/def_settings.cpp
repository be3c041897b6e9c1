#include "deferred/def_settings.h"

#include "core/gpu/context.h"

namespace tp::def {
namespace {

const ChoiceKnob<GBuffer>& gbufferKnob() {
    static const ChoiceKnob<GBuffer> k{
        "gbuffer",
        {{GBuffer::Compact, "compact"}, {GBuffer::Wide, "wide"}},
        "Deferred G-buffer layout: compact (8/16-bit) or wide (fp32)"};
    return k;
}

const ChoiceKnob<Lighting>& lightingKnob() {
    static const ChoiceKnob<Lighting> k{
        "deferred-lighting",
        {{Lighting::Tiled, "tiled"}, {Lighting::Volumes, "volumes"}},
        "Deferred lighting: tiled (compute, per-tile lists) or volumes (one draw per light)"};
    return k;
}

const ChoiceKnob<Prepass>& prepassKnob() {
    static const ChoiceKnob<Prepass> k{
        "gbuffer-prepass",
        {{Prepass::Auto, "auto"}, {Prepass::On, "on"}, {Prepass::Off, "off"}},
        "A depth prepass before deferred's G-buffer (the pass library's, as Forward+'s): on (the "
        "G-buffer then tests EQUAL and writes each sample's material once, not once per "
        "overlapping surface), off (the G-buffer pass writes depth itself) or auto (on for a GPU "
        "under MSAA; off at 1x, where a GPU's early depth test already rejects most hidden "
        "fragments, and on a CPU device such as lavapipe, docs/deferred.md \"The depth prepass\"); the "
        "same image either way"};
    return k;
}

} // namespace

bool prepassOn(const GpuContext& ctx, const Settings& s) {
    if (s.prepass != Prepass::Auto) return s.prepass == Prepass::On;
    return !ctx.isCpuDevice() && s.sampling.samples > 1;
}

KnobSchema knobs() {
    return {la::tileSizeKnob().knob(), la::lightCullKnob().knob(),
            la::lightBinKnob().knob(), la::lightAssignKnob().knob(),
            la::slicesKnob().knob(),   la::tileGroupKnob().knob(), gbufferKnob().knob(),
            prepassKnob().knob(),
            msaaShadingKnob().knob(), // pixel: Lauritzen 2010 edges; sample: supersampled deferred
            lightingKnob().knob(),     hdrKnob(),
            cullGeometryKnob().knob(), shadowRasterKnob().knob()};
}

Settings readSettings(const RenderSettings& s) {
    Settings d;
    d.width = s.width;
    d.height = s.height;
    d.sampling = readSampling(s);
    d.debug = s.debug;
    d.manyViews = s.manyViews;
    d.assign = la::readAssignSettings(s);
    d.tileGroup = la::tileGroupKnob().in(s);
    d.gbuffer = gbufferKnob().in(s);
    d.prepass = prepassKnob().in(s);
    d.lighting = lightingKnob().in(s);
    d.hdr = readHdr(s, HdrStorage::Fp32); // --hdr auto: fp32
    d.cullGeometry = cullGeometryKnob().in(s);
    d.shadowRaster = shadowRasterKnob().in(s);
    return d;
}

} // namespace tp::def
