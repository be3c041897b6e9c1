// The pipelines this build has. A new pipeline is a folder plus one line here.
#include "core/reference/reference_renderer.h"
#include "core/render/renderer.h"
#include "forwardplus/forwardplus_renderer.h"
#include "deferred/deferred_renderer.h"
#include "multipass_forward/multipass_renderer.h"

namespace tp {

void registerBuiltinRenderers() {
    registerRenderer({"reference",
                      "ground truth: every light at every sample, no culling, fp64 accumulation",
                      createReferenceRenderer});
    registerRenderer({"forwardplus",
                      "Forward+: depth prepass, per-tile light lists in compute, forward shading",
                      createForwardPlusRenderer});
    registerRenderer({"deferred", "G-buffer deferred: tiled compute lighting, hybrid forward pass for blended", createDeferredRenderer});
    registerRenderer({"multipass_forward", "one additive pass per light after a depth prepass", createMultipassForwardRenderer});
}

} // namespace tp
