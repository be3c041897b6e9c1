#pragma once
// EXR read/write (OpenEXR) and PNG write/read (stb_image_write, stb_image). One file per
// third-party library behind this header: exr_io.cpp, png_io.cpp.
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
// `display` as writePng stores it, read back: every channel rounded to 8 bits, / 255.
ImageRGBA asStoredInPng(ImageRGBA display);

// Reads an 8- or 16-bit PNG as display-space RGBA: each stored value / its maximum (255 or
// 65535), no transfer function undone; a grey or grey-alpha file fills R, G and B.
Result<ImageRGBA> readPng(const std::string& path);

} // namespace tp
