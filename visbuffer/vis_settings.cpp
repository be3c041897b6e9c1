#include "visbuffer/vis_settings.h"

#include "core/gpu/context.h"
#include "visbuffer/vis_shared.h"

namespace tp::vis {

const ChoiceKnob<Blended>& blendedKnob() {
    static const ChoiceKnob<Blended> k{
        "vis-blended",
        {{Blended::Compute, "compute"}, {Blended::Forward, "forward"}},
        "Where visbuffer shades blended surfaces: compute (a raster pass lists each pixel's "
        "blended fragment ids, the resolve composites them in the reference's order) or forward "
        "(the hybrid forward pass deferred uses: per-tile light lists, per-sample radiance under "
        "MSAA)"};
    return k;
}

const ChoiceKnob<Derivatives>& derivativesKnob() {
    static const ChoiceKnob<Derivatives> k{
        "vis-derivatives",
        {{Derivatives::Quad, "quad"},
         {Derivatives::Analytic, "analytic"},
         {Derivatives::QuadFine, "quad-fine"},
         {Derivatives::QuadCoarse, "quad-coarse"}},
        "visbuffer's texture footprint: quad (uv differences over the pixel's 2x2 quad on the "
        "same triangle's plane, coarse: one pair per quad, as lavapipe's fragment quads take them "
        "and as measured closest on an H200), analytic (the exact derivatives at the shaded "
        "point), or quad-fine / quad-coarse"};
    return k;
}

const ChoiceKnob<Raster>& rasterKnob() {
    static const ChoiceKnob<Raster> k{
        "vis-raster",
        {{Raster::Auto, "auto"},
         {Raster::Hardware, "hardware"},
         {Raster::Compute, "compute"},
         {Raster::Hybrid, "hybrid"}},
        "Who rasterizes visbuffer's opaque and masked triangles: auto (hybrid on a GPU at 1x "
        "without --cull-geometry full, where it measured fastest; hardware on a CPU device, "
        "under MSAA and with occlusion culling; counter vis_raster_mode says which ran: 0 "
        "hardware, 1 compute, 2 hybrid), hardware (the fixed-function "
        "visibility pass), compute (a compute rasterizer writes (depth, id) per sample with a "
        "64-bit atomic max: top-left rule, standard sample locations, near-plane clipping, the "
        "alpha test) or hybrid (triangles within 8x8 pixels in compute, the larger ones, those "
        "the near plane cuts and masked draws by the hardware, into the same visibility buffer). "
        "compute and hybrid need shaderInt64 and shaderBufferInt64Atomics (docs/visbuffer.md)"};
    return k;
}

const ChoiceKnob<Edges>& edgesKnob() {
    static const ChoiceKnob<Edges> k{
        "vis-edges",
        {{Edges::Auto, "auto"}, {Edges::Pixel, "pixel"}, {Edges::Split, "split"}},
        "How visbuffer's resolve lights its MSAA edge pixels at --msaa-shading pixel with "
        "--vis-blended compute: pixel (one invocation lights an edge pixel's surfaces and "
        "composites its blended fragments), split (only the edges with blended fragments so, "
        "the others flattened: one invocation a surface; 4x resolve on an H200 1.789 -> 1.655 ms, "
        "on lavapipe 1.27x slower) or auto (split on a GPU, pixel on a CPU device); the same "
        "image whichever"};
    return k;
}

Edges resolveEdges(const GpuContext& ctx, Edges e) {
    if (e != Edges::Auto) return e;
    return ctx.isCpuDevice() ? Edges::Pixel : Edges::Split;
}

Raster resolveRaster(const GpuContext& ctx, const Settings& s) {
    if (s.raster != Raster::Auto) return s.raster;
    const bool hybridPays = !ctx.isCpuDevice() && ctx.caps.int64Atomics &&
                            s.sampling.samples == 1 && s.cullGeometry != CullGeometry::Full;
    return hybridPays ? Raster::Hybrid : Raster::Hardware;
}

uint32_t resolveDerivatives(Derivatives d) {
    switch (d) {
    case Derivatives::Analytic: return TP_VIS_DERIVATIVES_ANALYTIC;
    case Derivatives::QuadFine: return TP_VIS_DERIVATIVES_QUAD_FINE;
    case Derivatives::QuadCoarse: return TP_VIS_DERIVATIVES_QUAD_COARSE;
    case Derivatives::Quad: break;
    }
    return TP_VIS_DERIVATIVES_QUAD_COARSE;
}

const IntegerKnob& blendedCapacityKnob() {
    static const IntegerKnob k{Knob::integer(
        "vis-blended-capacity", 0, 6400, 0,
        "visbuffer --vis-blended compute: blended fragments the lists hold (8 bytes each): 0 "
        "sizes them by a bound on the fragments the blended triangles can make on screen (none "
        "dropped); N holds N% of the pixel count, and fragments beyond are dropped and counted "
        "(blended_fragments_dropped, a warning), never silently")};
    return k;
}

uint32_t Settings::evaluationsPerPixel(bool blendedBudget) const {
    const uint32_t samples = sampling.samples;
    if (!blendedBudget || blended != Blended::Compute) return samples;
    return samples + kBlendedPerPixelBudget * (sampling.perSample() ? samples : 1);
}

KnobSchema knobs() {
    return {la::tileSizeKnob().knob(),
            la::lightCullKnob().knob(),
            la::lightBinKnob().knob(),
            la::lightAssignKnob().knob(),
            la::slicesKnob().knob(),
            la::tileGroupKnob().knob(),
            msaaShadingKnob().knob(), // pixel: once per pixel and triangle; sample: every sample
            hdrKnob(),
            blendedKnob().knob(),
            blendedCapacityKnob().knob(),
            derivativesKnob().knob(),
            cullGeometryKnob().knob(),
            rasterKnob().knob(),
            edgesKnob().knob(),
            shadowRasterKnob().knob()};
}

Settings readSettings(const RenderSettings& s) {
    Settings v;
    v.width = s.width;
    v.height = s.height;
    v.sampling = readSampling(s);
    v.debug = s.debug;
    v.manyViews = s.manyViews;
    v.assign = la::readAssignSettings(s);
    v.tileGroup = la::tileGroupKnob().in(s);
    v.hdr = readHdr(s, HdrStorage::Fp32); // --hdr auto: fp32
    v.blended = blendedKnob().in(s);
    v.blendedCapacityPercent = blendedCapacityKnob().in(s);
    v.derivatives = derivativesKnob().in(s);
    v.cullGeometry = cullGeometryKnob().in(s);
    v.raster = rasterKnob().in(s);
    v.edges = edgesKnob().in(s);
    v.shadowRaster = shadowRasterKnob().in(s);
    if (auto seen = s.capacities.find(kSeenFragments); seen != s.capacities.end())
        v.blendedSeen = seen->second;
    return v;
}

} // namespace tp::vis
