// The reference as the rest of the program sees it: the ground truth every pipeline is
// measured against, and its knobs.
#include "core/reference/reference_renderer.h"
#include "core/render/renderer.h"

namespace tp {
namespace {

KnobSchema referenceKnobs() {
    return {Knob::choice("reference-precision", {"fp64", "fp32"},
                         "Light-sum accumulation of the reference (fp64 needs shaderFloat64)")
                .fixed(),
            Knob::choice("reference-msaa", {"sample", "center"},
                         "Reference under MSAA: sample (every sample shaded at its own location: supersampling, the "
                         "ground truth) or center (every covered sample shaded with the inputs at the pixel centre, a "
                         "masked surface's alpha still tested per sample: what shading once per pixel with per-sample "
                         "coverage gives; the error against it leaves out the shading rate)")
                .onlyUnderMsaa()
                .fixed(),
            Knob::choice("reference-position", {"interpolated", "depth"},
                         "Position the reference lights opaque and masked surfaces at: interpolated (the vertex "
                         "shader's, the ground truth) or depth (reconstructed from the sample's own depth exactly as "
                         "a deferred pipeline does: for separating a deferred pipeline's position-reconstruction "
                         "error, depth against interpolated, from its other errors, deferred against depth). "
                         "Blended surfaces keep the interpolated position, as deferred lights them forward")
                .fixed()};
}

// The reference is measured against itself: its model is never asked for.
const RendererRegistration registration{{kReferenceRenderer,
                                         "ground truth: every light at every sample, no culling, fp64 accumulation",
                                         createReferenceRenderer, 0, referenceKnobs(), {}, {}}};

} // namespace
} // namespace tp
