#pragma once
// Deferred's precision model for `triptych stress` (docs/stress.md): positions from depth,
// the compact G-buffer's quantization, shading once per pixel under MSAA, and the fp16 hdr
// target's roundings (--hdr fp16).
#include "core/renderer/error_model.h"

namespace tp {

void deferredErrorModel(ErrorBound& b, const ErrorModelInput& in);

} // namespace tp
