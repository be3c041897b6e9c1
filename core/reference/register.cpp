// The reference as the rest of the program sees it: the ground truth every pipeline is
// measured against, and its knobs.
#include "core/reference/reference_renderer.h"
#include "core/reference/reference_settings.h"
#include "core/renderer/renderer.h"

namespace tp {
namespace {

// The reference is measured against itself: its model is never asked for.
const RendererRegistration registration{
    {kReferenceRenderer,
     "ground truth: every light at every sample, no culling, fp64 accumulation",
     createReferenceRenderer,
     0,
     ref::knobs(),
     {},
     {}}};

} // namespace
} // namespace tp
