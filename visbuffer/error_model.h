#pragma once
// The visibility buffer's precision model for `triptych stress` and the tests
// (docs/visbuffer.md, "Error model"): the exact hit against unsnapped vertices next to
// lights, shading once per pixel and triangle under MSAA, the fp16 hdr target's roundings.
#include "core/renderer/error_model.h"

namespace tp {

void visbufferErrorModel(ErrorBound& b, const ErrorModelInput& in);

} // namespace tp
