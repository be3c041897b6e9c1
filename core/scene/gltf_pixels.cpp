// Decoded image pixels (stb: 1 to 4 channels, 8 or 16 bits) to the RGBA8 every texture is
// uploaded as (gltf_materials.cpp decodes, this converts).
#include <cstdint>
#include <vector>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {

bool toRgba8(const unsigned char* data, size_t size, int width, int height, int components,
             int bits, std::vector<uint8_t>& rgba8) {
    if (width <= 0 || height <= 0 || components < 1 || components > 4 || (bits != 8 && bits != 16))
        return false;
    const size_t pixels = size_t(width) * size_t(height);
    const size_t bytesPerChannel = size_t(bits / 8);
    if (size < pixels * size_t(components) * bytesPerChannel) return false;
    rgba8.resize(pixels * 4);
    auto channel = [&](size_t i) -> uint8_t {
        if (bits == 8) return data[i];
        uint16_t v = uint16_t(data[2 * i] | data[2 * i + 1] << 8); // stb: native (little) endian
        return uint8_t((uint32_t(v) * 255u + 32767u) / 65535u);
    };
    for (size_t p = 0; p < pixels; ++p) {
        const size_t s = p * size_t(components);
        uint8_t* d = &rgba8[p * 4];
        if (components <= 2) {
            d[0] = d[1] = d[2] = channel(s);
            d[3] = components == 2 ? channel(s + 1) : 255;
        } else {
            d[0] = channel(s), d[1] = channel(s + 1), d[2] = channel(s + 2);
            d[3] = components == 4 ? channel(s + 3) : 255;
        }
    }
    return true;
}

} // namespace tp::gltf
