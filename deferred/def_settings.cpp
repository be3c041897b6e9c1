#include "deferred/def_settings.h"

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

} // namespace

KnobSchema knobs() {
    return {la::tileSizeKnob().knob(), la::lightCullKnob().knob(),
            la::lightBinKnob().knob(), la::lightAssignKnob().knob(),
            la::slicesKnob().knob(),   la::tileGroupKnob().knob(), gbufferKnob().knob(),
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
    d.lighting = lightingKnob().in(s);
    d.hdr = readHdr(s, HdrStorage::Fp32); // --hdr auto: fp32
    d.cullGeometry = cullGeometryKnob().in(s);
    d.shadowRaster = shadowRasterKnob().in(s);
    return d;
}

} // namespace tp::def
