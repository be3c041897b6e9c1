// The compute rasterizer's own specialization constants (include/raster_triangle.glsl), set
// from the device for both of its users: the visibility buffer's (visbuffer/raster_pass.cpp)
// and the shadow maps' (core/passes/shadow_raster.cpp).
#pragma once

#include <vector>

#include "core/gpu/context.h"
#include "core/gpu/pipelines.h"
#include "include/raster_triangle.h"

namespace tp {

// The device's sub-pixel bits, and its triangle setup: llvmpipe sets the depth plane up from
// the float positions and rounds the viewport transform its own way, a GPU from the snapped
// ones (measured on the H200).
inline std::vector<SpecConstant> rasterTriangleConstants(const GpuContext& ctx) {
    return {{TP_RT_SPEC_SUBPIXEL_BITS, ctx.properties.limits.subPixelPrecisionBits},
            {TP_RT_SPEC_GPU_SETUP, ctx.isCpuDevice() ? 0u : 1u}};
}

} // namespace tp
