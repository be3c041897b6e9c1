#pragma once
// The reference: the ground truth every pipeline is measured against. One pass: for every
// pixel (every sample when MSAA is on: per-sample shading), every light is evaluated, with
// no culling and no intermediate storage; the light sum accumulates in fp64 where the
// device has shaderFloat64 (selectable), else fp32. Opaque and masked geometry first, then
// blended geometry back to front, blended in a 32-bit float target. Under MSAA,
// --reference-msaa center shades every sample with the inputs at the pixel centre but keeps
// per-sample coverage: a masked surface is alpha-tested at each sample, as the pipelines'
// per-sample masked prepass does (docs/shading.md).
#include <memory>

#include "core/renderer/renderer.h"

namespace tp {

// The registered name of the reference: compare, sweep and stress render it as the ground
// truth whatever pipelines are selected.
inline constexpr const char* kReferenceRenderer = "reference";

std::unique_ptr<Renderer> createReferenceRenderer(const RendererCreateInfo& info);

} // namespace tp
