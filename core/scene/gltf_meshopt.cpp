// EXT_meshopt_compression: bufferViews whose bytes are stored compressed in another buffer,
// decoded by meshoptimizer before any accessor is read. One of the two files that include
// meshoptimizer (STYLE.md, lesson 15: the other builds meshlets, core/scene/meshlets.cpp).
#include <meshoptimizer.h>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";

// meshoptimizer's codecs cannot shrink data past these ratios (vertex codec: 2 header bits per
// 16-byte group at best, so 1/64; index codecs: a byte per triangle or index at least), so a
// view declaring more is corrupt, and its decoded size is bounded by the file's.
constexpr uint64_t kMaxRatio = 64;
constexpr uint64_t kSlack = 4096;

// The extension's fields (-1: missing or not a whole non-negative number).
struct MeshoptView {
    int64_t buffer, offset, length, stride, count;
    std::string mode, filter;
};

MeshoptView readFields(const tinygltf::Value& ext) {
    auto number = [&](const char* key, int64_t fallback) -> int64_t {
        const tinygltf::Value& n = ext.Get(key);
        if (!n.IsNumber()) return fallback;
        double d = n.GetNumberAsDouble();
        return d >= 0 && d < 9e15 && d == double(int64_t(d)) ? int64_t(d) : -1;
    };
    auto text = [&](const char* key, const char* fallback) {
        const tinygltf::Value& s = ext.Get(key);
        return s.IsString() ? s.Get<std::string>() : std::string(fallback);
    };
    return {number("buffer", -1),     number("byteOffset", 0), number("byteLength", -1),
            number("byteStride", -1), number("count", -1),     text("mode", ""),
            text("filter", "NONE")};
}

// Decodes `in` (m.length bytes) into `out` (count x stride bytes) with the mode's codec,
// then undoes the filter.
Status runCodec(const MeshoptView& m, const unsigned char* in, std::vector<unsigned char>& out) {
    const std::string& mode = m.mode;
    const int64_t count = m.count, stride = m.stride, length = m.length;
    int rc = -1;
    if (mode == "ATTRIBUTES") {
        if (stride % 4 != 0) return Error{"ATTRIBUTES byteStride is not a multiple of 4"};
        rc = meshopt_decodeVertexBuffer(out.data(), size_t(count), size_t(stride), in,
                                        size_t(length));
    } else if (mode == "TRIANGLES" || mode == "INDICES") {
        if (stride != 2 && stride != 4) return Error{"index byteStride is not 2 or 4"};
        if (mode == "TRIANGLES" && count % 3 != 0)
            return Error{"TRIANGLES count is not a multiple of 3"};
        rc = mode == "TRIANGLES" ? meshopt_decodeIndexBuffer(out.data(), size_t(count),
                                                             size_t(stride), in, size_t(length))
                                 : meshopt_decodeIndexSequence(out.data(), size_t(count),
                                                               size_t(stride), in, size_t(length));
    } else {
        return Error{"unknown mode \"" + mode + "\""};
    }
    if (rc != 0)
        return Error{"the compressed data is corrupt or truncated (meshoptimizer " +
                     std::to_string(rc) + ")"};
    const std::string& filter = m.filter;
    if (filter == "OCTAHEDRAL" && mode == "ATTRIBUTES" && (stride == 4 || stride == 8))
        meshopt_decodeFilterOct(out.data(), size_t(count), size_t(stride));
    else if (filter == "QUATERNION" && mode == "ATTRIBUTES" && stride == 8)
        meshopt_decodeFilterQuat(out.data(), size_t(count), size_t(stride));
    else if (filter == "EXPONENTIAL" && mode == "ATTRIBUTES")
        meshopt_decodeFilterExp(out.data(), size_t(count), size_t(stride));
    else if (filter != "NONE")
        return Error{"filter " + filter + " does not fit mode " + mode + " and byteStride " +
                     std::to_string(stride)};
    return {};
}

// Bufferview `v`: its fields checked against the buffers and its own byteLength, decoded into
// a buffer of its own that the view then reads.
Status decodeView(tinygltf::Model& model, size_t v, const tinygltf::Value& ext) {
    tinygltf::BufferView& view = model.bufferViews[v];
    const MeshoptView m = readFields(ext);
    if (m.buffer < 0 || size_t(m.buffer) >= model.buffers.size())
        return Error{"buffer " + std::to_string(m.buffer) + " does not exist"};
    const std::vector<unsigned char>& src = model.buffers[size_t(m.buffer)].data;
    if (m.offset < 0 || m.length < 0 || uint64_t(m.offset) > src.size() ||
        uint64_t(m.length) > src.size() - uint64_t(m.offset))
        return Error{"compressed bytes " + std::to_string(m.offset) + "+" +
                     std::to_string(m.length) + " lie outside buffer " + std::to_string(m.buffer) +
                     " of " + std::to_string(src.size()) + " bytes"};
    if (m.count < 0 || m.stride < 1 || m.stride > 256)
        return Error{"count or byteStride missing or out of range"};
    const uint64_t size = uint64_t(m.count) * uint64_t(m.stride);
    if (size != view.byteLength)
        return Error{"count x byteStride is " + std::to_string(size) +
                     " bytes, the bufferView's byteLength " + std::to_string(view.byteLength)};
    if (size > uint64_t(m.length) * kMaxRatio + kSlack)
        return Error{std::to_string(m.length) + " compressed bytes cannot hold " +
                     std::to_string(size) + " bytes"};
    std::vector<unsigned char> out(size_t(size), 0);
    if (Status s = runCodec(m, src.data() + m.offset, out); !s) return s;
    tinygltf::Buffer decoded;
    decoded.name = "decoded " + std::to_string(v);
    decoded.data = std::move(out);
    model.buffers.push_back(std::move(decoded));
    view.buffer = int(model.buffers.size() - 1);
    view.byteOffset = 0;
    return {};
}

} // namespace

Status decodeMeshopt(tinygltf::Model& model, bool& any) {
    any = false;
    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        const tinygltf::ExtensionMap& extensions = model.bufferViews[v].extensions;
        auto found = extensions.find(kMeshopt);
        if (found == extensions.end()) continue;
        any = true;
        const std::string what = "bufferView " + std::to_string(v) + ": " + kMeshopt;
        if (!found->second.IsObject()) return Error{what + " is not an object"};
        if (Status s = decodeView(model, v, found->second); !s)
            return Error{what + ": " + s.error()};
    }
    return {};
}

} // namespace tp::gltf
