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
            "(the shadow maps the pipelines sample, with their filter: compare renders it as the second "
            "reference, docs/shadows.md). No effect without shadowed lights"}
            .fixed();
    return k;
}

} // namespace

KnobSchema knobs() {
    return {precisionKnob().knob(), msaaKnob().knob(), positionKnob().knob(), shadowsKnob().knob()};
}

Settings readSettings(const RenderSettings& s) {
    return {precisionKnob().in(s), msaaKnob().in(s), positionKnob().in(s), shadowsKnob().in(s)};
}

} // namespace tp::ref
