#include "core/reference/reference_settings.h"

namespace tp::ref {
namespace {

const ChoiceKnob<Precision>& precisionKnob() {
    static const ChoiceKnob<Precision> k =
        ChoiceKnob<Precision>{"reference-precision",
                              {{Precision::Fp64, "fp64"}, {Precision::Fp32, "fp32"}},
                              "Light-sum accumulation of the reference (fp64 needs shaderFloat64)"}
            .fixed();
    return k;
}

const ChoiceKnob<MsaaMode>& msaaKnob() {
    static const ChoiceKnob<MsaaMode> k =
        ChoiceKnob<MsaaMode>{"reference-msaa",
                             {{MsaaMode::Sample, "sample"}, {MsaaMode::Center, "center"}},
                             "Reference under MSAA: sample (every sample shaded at its own "
                             "location: supersampling, the "
                             "ground truth) or center (every covered sample shaded with the inputs "
                             "at the pixel centre, a "
                             "masked surface's alpha still tested per sample: what shading once "
                             "per pixel with per-sample "
                             "coverage gives; the error against it leaves out the shading rate)"}
            .onlyUnderMsaa()
            .fixed();
    return k;
}

const ChoiceKnob<Position>& positionKnob() {
    static const ChoiceKnob<Position> k =
        ChoiceKnob<Position>{
            "reference-position",
            {{Position::Interpolated, "interpolated"}, {Position::Depth, "depth"}},
            "Position the reference lights opaque and masked surfaces at: interpolated (the vertex "
            "shader's, the ground truth) or depth (reconstructed from the sample's own depth "
            "exactly as "
            "a deferred pipeline does: for separating a deferred pipeline's "
            "position-reconstruction "
            "error, depth against interpolated, from its other errors, deferred against depth). "
            "Blended surfaces keep the interpolated position, as deferred lights them forward"}
            .fixed();
    return k;
}

const ChoiceKnob<Shadows>& shadowsKnob() {
    static const ChoiceKnob<Shadows> k =
        ChoiceKnob<Shadows>{
            "reference-shadows",
            {{Shadows::Rays, "rays"}, {Shadows::Maps, "maps"}},
            "Visibility of the shadowed lights in the reference: rays (a shadow ray per sample "
            "and light against the opaque and masked triangles, through a BVH: exact) or maps "
            "(the shadow maps the pipelines sample, with their filter, rasterized as their "
            "--shadow-raster says, with the face cull of their --cull-geometry under compute: "
            "compare renders it as the second reference, docs/shadows.md). No effect without "
            "shadowed lights"}
            .fixed();
    return k;
}

// The maps' rasterizer, from the pipelines' knobs (Settings::mapsRaster says why). Hardware
// maps are drawn whole (the same texels as culled ones: the cull drops only what a face cannot
// see); the compute rasterizer reads what the face cull keeps, which frustum and full cull
// alike (a face's frustum and the light's range, no occlusion), so one key serves both.
void readMapsRaster(const RenderSettings& s, Settings& r) {
    r.mapsRaster = shadowRasterKnob().carriedIn(s);
    if (r.mapsRaster == ShadowRaster::Compute &&
        cullGeometryKnob().carriedIn(s) != CullGeometry::None)
        r.mapsCull = CullGeometry::Frustum;
}

} // namespace

KnobSchema knobs() {
    return {precisionKnob().knob(), msaaKnob().knob(), positionKnob().knob(), shadowsKnob().knob()};
}

Settings readSettings(const RenderSettings& s) {
    Settings r{precisionKnob().in(s), msaaKnob().in(s), positionKnob().in(s), shadowsKnob().in(s)};
    readMapsRaster(s, r);
    return r;
}

std::string followedSettingsText(const RenderSettings& s) {
    if (!s.shadows.enabled() || shadowsKnob().carriedIn(s) != Shadows::Maps) return {};
    Settings r;
    readMapsRaster(s, r);
    std::string t = "maps raster " + shadowRasterKnob().text(r.mapsRaster);
    t += " cull " + cullGeometryKnob().text(r.mapsCull) + "\n";
    return t;
}

} // namespace tp::ref
