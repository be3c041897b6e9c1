// EXT_meshopt_compression: bufferViews whose bytes are stored compressed in another buffer,
// decoded by meshoptimizer before any accessor is read. The only file that includes
// meshoptimizer (STYLE.md, lesson 15).
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

} // namespace

Status decodeMeshopt(tinygltf::Model& model, bool& any) {
    any = false;
    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        tinygltf::BufferView& view = model.bufferViews[v];
        auto found = view.extensions.find(kMeshopt);
        if (found == view.extensions.end()) continue;
        any = true;
        const std::string what = "bufferView " + std::to_string(v) + ": " + kMeshopt;
        const tinygltf::Value& ext = found->second;
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
        if (!ext.IsObject()) return Error{what + " is not an object"};
        const int64_t buffer = number("buffer", -1), offset = number("byteOffset", 0),
                      length = number("byteLength", -1), stride = number("byteStride", -1),
                      count = number("count", -1);
        const std::string mode = text("mode", ""), filter = text("filter", "NONE");
        if (buffer < 0 || size_t(buffer) >= model.buffers.size())
            return Error{what + ": buffer " + std::to_string(buffer) + " does not exist"};
        const std::vector<unsigned char>& src = model.buffers[size_t(buffer)].data;
        if (offset < 0 || length < 0 || uint64_t(offset) > src.size() ||
            uint64_t(length) > src.size() - uint64_t(offset))
            return Error{what + ": compressed bytes " + std::to_string(offset) + "+" +
                         std::to_string(length) + " lie outside buffer " + std::to_string(buffer) +
                         " of " + std::to_string(src.size()) + " bytes"};
        if (count < 0 || stride < 1 || stride > 256)
            return Error{what + ": count or byteStride missing or out of range"};
        const uint64_t size = uint64_t(count) * uint64_t(stride);
        if (size != view.byteLength)
            return Error{what + ": count x byteStride is " + std::to_string(size) +
                         " bytes, the bufferView's byteLength " + std::to_string(view.byteLength)};
        if (size > uint64_t(length) * kMaxRatio + kSlack)
            return Error{what + ": " + std::to_string(length) + " compressed bytes cannot hold " +
                         std::to_string(size) + " bytes"};
        std::vector<unsigned char> out(size_t(size), 0);
        const unsigned char* in = src.data() + offset;
        int rc = -1;
        if (mode == "ATTRIBUTES") {
            if (stride % 4 != 0) return Error{what + ": ATTRIBUTES byteStride is not a multiple of 4"};
            rc = meshopt_decodeVertexBuffer(out.data(), size_t(count), size_t(stride), in,
                                            size_t(length));
        } else if (mode == "TRIANGLES" || mode == "INDICES") {
            if (stride != 2 && stride != 4) return Error{what + ": index byteStride is not 2 or 4"};
            if (mode == "TRIANGLES" && count % 3 != 0)
                return Error{what + ": TRIANGLES count is not a multiple of 3"};
            rc = mode == "TRIANGLES"
                     ? meshopt_decodeIndexBuffer(out.data(), size_t(count), size_t(stride), in,
                                                 size_t(length))
                     : meshopt_decodeIndexSequence(out.data(), size_t(count), size_t(stride), in,
                                                   size_t(length));
        } else {
            return Error{what + ": unknown mode \"" + mode + "\""};
        }
        if (rc != 0)
            return Error{what + ": the compressed data is corrupt or truncated (meshoptimizer " +
                         std::to_string(rc) + ")"};
        if (filter == "OCTAHEDRAL" && mode == "ATTRIBUTES" && (stride == 4 || stride == 8))
            meshopt_decodeFilterOct(out.data(), size_t(count), size_t(stride));
        else if (filter == "QUATERNION" && mode == "ATTRIBUTES" && stride == 8)
            meshopt_decodeFilterQuat(out.data(), size_t(count), size_t(stride));
        else if (filter == "EXPONENTIAL" && mode == "ATTRIBUTES")
            meshopt_decodeFilterExp(out.data(), size_t(count), size_t(stride));
        else if (filter != "NONE")
            return Error{what + ": filter " + filter + " does not fit mode " + mode +
                         " and byteStride " + std::to_string(stride)};
        // The view now reads the decoded bytes, from a buffer of their own.
        tinygltf::Buffer decoded;
        decoded.name = "decoded " + std::to_string(v);
        decoded.data = std::move(out);
        model.buffers.push_back(std::move(decoded));
        view.buffer = int(model.buffers.size() - 1);
        view.byteOffset = 0;
    }
    return {};
}

} // namespace tp::gltf
