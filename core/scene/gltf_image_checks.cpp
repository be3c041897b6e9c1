// An encoded image checked before stb_image decodes it: its size from the PNG or JPEG header
// (peekImageSize; loadMaterials bounds it), then a PNG's chunks and image data. stb trusts
// what the file says: it grows its compressed-data buffer to each IDAT chunk's declared length
// before reading it (a 26 KB file made it realloc 2 GiB), and its output buffer for as long as
// the zlib stream produces bytes (deflate expands up to 1032:1). So the chunks are walked
// first, and the stream is inflated here through a small window, counting, before stb
// allocates anything.
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
namespace {

uint32_t be32(const unsigned char* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

// "'IDAT'", or the type in hex when it is not four letters (a damaged one).
std::string chunkName(const unsigned char* type) {
    bool letters = true;
    for (int i = 0; i < 4; ++i)
        letters = letters && std::isalpha(type[i]);
    static const char hex[] = "0123456789abcdef";
    std::string out = letters ? "'" : "0x";
    for (int k = 0; k < 4; ++k) {
        if (letters)
            out += char(type[k]);
        else
            out += {hex[type[k] >> 4], hex[type[k] & 15]};
    }
    if (letters) out += '\'';
    return out;
}

// Bytes of filtered scanlines the image needs (a filter byte per row), Adam7 passes summed.
uint64_t scanlineBytes(uint32_t width, uint32_t height, int bitsPerPixel, bool interlaced) {
    auto pass = [&](uint64_t w, uint64_t h) {
        return w && h ? ((w * uint64_t(bitsPerPixel) + 7) / 8 + 1) * h : 0;
    };
    if (!interlaced) return pass(width, height);
    static const int xo[7] = {0, 4, 0, 2, 0, 1, 0}, yo[7] = {0, 0, 4, 0, 2, 0, 1};
    static const int xs[7] = {8, 8, 4, 4, 2, 2, 1}, ys[7] = {8, 8, 8, 4, 4, 2, 2};
    uint64_t total = 0;
    for (int p = 0; p < 7; ++p)
        total += pass((uint64_t(width) + uint64_t(xs[p] - xo[p] - 1)) / uint64_t(xs[p]),
                      (uint64_t(height) + uint64_t(ys[p] - yo[p] - 1)) / uint64_t(ys[p]));
    return total;
}

// Inflates the concatenated IDAT data through a 64 KiB window; "" when it ends within `limit`
// bytes of output. zlib, not stb: stb has no way to stop at a limit. A stream zlib calls
// corrupt is refused (stb's inflater accepts nothing zlib refuses, save a bad checksum, which
// raw inflation here does not check either).
std::string inflatedWithin(const std::vector<std::pair<const unsigned char*, uint32_t>>& idat,
                           bool zlibHeader, uint64_t limit) {
    z_stream z{};
    if (inflateInit2(&z, -MAX_WBITS) != Z_OK) return "zlib cannot start";
    std::vector<unsigned char> window(64 * 1024);
    uint64_t produced = 0;
    size_t skip = zlibHeader ? 2 : 0; // stb checks the 2-byte header itself
    int status = Z_OK;
    for (size_t c = 0; c < idat.size() && status == Z_OK; ++c) {
        const size_t drop = std::min<size_t>(skip, idat[c].second);
        skip -= drop;
        z.next_in = const_cast<unsigned char*>(idat[c].first + drop);
        z.avail_in = uInt(idat[c].second - drop);
        do {
            z.next_out = window.data();
            z.avail_out = uInt(window.size());
            status = inflate(&z, Z_NO_FLUSH);
            produced += window.size() - z.avail_out;
            if (status == Z_BUF_ERROR) status = Z_OK; // wants the next chunk's bytes
        } while (status == Z_OK && produced <= limit && (z.avail_in > 0 || z.avail_out == 0));
        if (produced > limit) break;
    }
    const std::string message = z.msg ? z.msg : "error";
    inflateEnd(&z);
    if (produced > limit)
        return "its image data inflates to more than " + std::to_string(limit) +
               " bytes, twice what its size needs";
    // A stream that stops short is stb's to refuse; it allocates nothing more for it.
    if (status != Z_OK && status != Z_STREAM_END)
        return "its compressed image data is corrupt (zlib: " + message + ")";
    return "";
}

} // namespace

bool peekImageSize(const unsigned char* b, size_t size, int& width, int& height) {
    static const unsigned char kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size >= 24 && std::equal(kPng, kPng + 8, b)) {
        if (!std::equal(b + 12, b + 16, "IHDR")) return false;
        uint32_t w = be32(b + 16), h = be32(b + 20);
        if (w == 0 || h == 0 || w > INT32_MAX || h > INT32_MAX) return false;
        width = int(w), height = int(h);
        return true;
    }
    if (size < 4 || b[0] != 0xFF || b[1] != 0xD8) return false;
    size_t i = 2;
    while (i + 3 < size) {
        if (b[i] != 0xFF) return false;
        unsigned char m = b[i + 1];
        if (m == 0xFF) { // fill byte
            ++i;
            continue;
        }
        if (m == 0x01 || (m >= 0xD0 && m <= 0xD8)) { // markers without a length
            i += 2;
            continue;
        }
        size_t length = size_t(b[i + 2]) << 8 | b[i + 3];
        bool sof = m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
        if (sof) {
            if (i + 9 > size || length < 7) return false;
            height = int(b[i + 5]) << 8 | b[i + 6];
            width = int(b[i + 7]) << 8 | b[i + 8];
            return width > 0 && height > 0;
        }
        if (m == 0xDA || m == 0xD9 || length < 2) return false; // image data before any SOF
        i += 2 + length;
    }
    return false;
}

std::string checkPng(const unsigned char* b, size_t size, std::vector<unsigned char>& cleaned) {
    cleaned.clear();
    std::vector<std::pair<const unsigned char*, uint32_t>> idat;
    bool iphone = false, emptyIdat = false, ihdr = false;
    uint32_t width = 0, height = 0;
    int bitsPerPixel = 0;
    bool interlaced = false;
    size_t p = 8;
    for (;;) {
        if (p + 12 > size) return "it ends before its IEND chunk";
        const uint32_t length = be32(b + p);
        const unsigned char* type = b + p + 4;
        // The spec's limit is 2^31 - 1; either way the chunk must lie inside the image.
        if (length > size - p - 12)
            return "its chunk " + chunkName(type) + " of " + std::to_string(length) +
                   " bytes runs past the end of the image (" + std::to_string(size) + " bytes)";
        const unsigned char* data = b + p + 8;
        if (std::memcmp(type, "CgBI", 4) == 0) iphone = true;
        if (std::memcmp(type, "IHDR", 4) == 0 && length == 13) {
            width = be32(data), height = be32(data + 4);
            static const int channels[7] = {1, 0, 3, 1, 2, 0, 4};
            const int depth = data[8], color = data[9];
            if (color > 6 || channels[color] == 0 || depth == 0 || depth > 16)
                return "its IHDR chunk holds an invalid colour type or bit depth";
            bitsPerPixel = channels[color] * depth;
            interlaced = data[12] != 0;
            ihdr = true;
        }
        if (std::memcmp(type, "IDAT", 4) == 0) {
            if (length == 0)
                emptyIdat = true;
            else
                idat.push_back({data, length});
        }
        p += 12 + size_t(length);
        if (std::memcmp(type, "IEND", 4) == 0) break;
    }
    // An empty IDAT carries nothing, but stb copies it into its not yet allocated buffer
    // (memcpy to a null pointer) when it comes first: decode a copy without the empty ones (also
    // when every IDAT is empty: stb then refuses the copy for having none).
    if (emptyIdat) {
        cleaned.assign(b, b + 8);
        for (size_t q = 8; q < p;) {
            const size_t chunk = 12 + size_t(be32(b + q));
            if (!(be32(b + q) == 0 && std::memcmp(b + q + 4, "IDAT", 4) == 0))
                cleaned.insert(cleaned.end(), b + q, b + q + chunk);
            q += chunk;
        }
    }
    if (!ihdr || idat.empty()) return ""; // stb refuses it before allocating for the data
    const uint64_t needed = scanlineBytes(width, height, bitsPerPixel, interlaced);
    return inflatedWithin(idat, !iphone, 2 * needed);
}

} // namespace tp::gltf
