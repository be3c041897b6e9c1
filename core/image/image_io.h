#pragma once
// EXR read/write (OpenEXR) and PNG write (stb_image_write). One file per third-party library
// behind this header: exr_io.cpp, png_io.cpp.
#include <string>

#include "core/image/image.h"
#include "core/util/result.h"

namespace tp {

enum class ExrPixelType { Half, Float };

// Writes linear RGBA. Fails with a one-line message naming the path.
Status writeExr(const std::string& path, const ImageRGBA& image, ExrPixelType type);
Result<ImageRGBA> readExr(const std::string& path);

// Writes 8-bit sRGB RGBA (alpha forced to 255 unless keepAlpha), values already in [0,1]
// display space; no tonemapping is done here.
Status writePng(const std::string& path, const ImageRGBA& display, bool keepAlpha = false);

} // namespace tp
