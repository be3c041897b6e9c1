#pragma once
// The G-buffer deferred pipeline ("deferred"): a G-buffer pass (opaque + masked), tiled
// lighting in compute, and the hybrid forward pass for blended materials. Publishes "hdr"
// (--hdr fp32, the default: RGBA32F, the light sum stays fp32 from compute to readback, so
// `wide` isolates the G-buffer as the only precision choice; --hdr fp16: RGBA16F as
// Forward+'s, half the bytes, one fp16 rounding per store) and "depth" (D32, MSAA: sample 0).
#include <memory>

#include "core/renderer/renderer.h"

namespace tp {

std::unique_ptr<Renderer> createDeferredRenderer(const RendererCreateInfo& info);

} // namespace tp
