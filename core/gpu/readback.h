#pragma once
// Readback of any image to the CPU. The image must be in TRANSFER_SRC_OPTIMAL layout with
// its writes made available (exported frame-graph outputs are left that way).
#include "core/gpu/resources.h"
#include "core/image/image.h"

namespace tp {

class GpuContext;

// Colour formats RGBA32F, RGBA16F, RGBA8 (UNORM/SRGB: raw values / 255), R32F; the result
// has row 0 at the top.
ImageRGBA readbackColor(GpuContext& ctx, const Image& image);
// D32_SFLOAT depth (reverse-Z: 1 at the near plane, 0 at infinity / no geometry).
ImageR32 readbackDepth(GpuContext& ctx, const Image& image);
// n half floats (IEEE binary16) to float, exactly: F16C where the CPU has it (the viewer reads
// back a 1080p RGBA16F image per view), glm otherwise.
void halfToFloat(const uint16_t* src, float* dst, size_t n);
// Raw bytes of a buffer (must have been created with TRANSFER_SRC usage).
std::vector<uint8_t> readbackBuffer(GpuContext& ctx, const Buffer& buffer);

} // namespace tp
