// glTF accessors, read only after their bufferView, buffer and byte ranges (and those of a
// sparse part) are checked against the bytes tinygltf actually loaded.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
namespace {

size_t componentSize(int type) {
    switch (type) {
    case kByte:
    case kUByte:
        return 1;
    case kShort:
    case kUShort:
        return 2;
    case kUInt:
    case kFloat:
        return 4;
    default:
        return 0;
    }
}

size_t componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2:
        return 4;
    case TINYGLTF_TYPE_MAT3:
        return 9;
    case TINYGLTF_TYPE_MAT4:
        return 16;
    default:
        return 0;
    }
}

const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    default:
        return "a matrix";
    }
}

// offset + size <= limit without overflow.
bool fits(uint64_t offset, uint64_t size, uint64_t limit) {
    return offset <= limit && size <= limit - offset;
}

Error accessorError(size_t index, const std::string& what) {
    return Error{"accessor " + std::to_string(index) + ": " + what};
}

// Where a byte range of `view` lies: checks the view against its buffer and returns its data.
Status resolveView(const tinygltf::Model& model, size_t accessor, int viewIndex, uint64_t offset,
                   uint64_t span, const char* role, const uint8_t*& data) {
    std::string prefix = std::string(role) + "bufferView " + std::to_string(viewIndex);
    if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
        return accessorError(accessor, prefix + " does not exist (the file has " +
                                           std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        return accessorError(accessor, prefix + " refers to buffer " + std::to_string(view.buffer) +
                                           ", which does not exist");
    const std::vector<unsigned char>& bytes = model.buffers[size_t(view.buffer)].data;
    if (!fits(view.byteOffset, view.byteLength, bytes.size()))
        return accessorError(accessor, prefix + " (bytes " + std::to_string(view.byteOffset) + "+" +
                                           std::to_string(view.byteLength) +
                                           ") lies outside its buffer of " +
                                           std::to_string(bytes.size()) + " bytes");
    if (!fits(offset, span, view.byteLength))
        return accessorError(accessor, std::string(role) + "data (bytes " + std::to_string(offset) +
                                           "+" + std::to_string(span) +
                                           ") lies outside bufferView " +
                                           std::to_string(viewIndex) + " of " +
                                           std::to_string(view.byteLength) + " bytes");
    data = bytes.data() + view.byteOffset + offset;
    return {};
}

// A checked accessor: element i starts at data + i * stride (data == nullptr: all zeros).
struct Located {
    const uint8_t* data = nullptr;
    size_t stride = 0;
    size_t elementSize = 0;
    size_t componentSize = 0;
    const uint8_t* sparseIndices = nullptr;
    const uint8_t* sparseValues = nullptr;
};

Status locate(const tinygltf::Model& model, size_t index, Located& out, bool compressed = false) {
    if (index >= model.accessors.size())
        return Error{"accessor " + std::to_string(index) + " does not exist (the file has " +
                     std::to_string(model.accessors.size()) + ")"};
    const tinygltf::Accessor& a = model.accessors[index];
    out.componentSize = componentSize(a.componentType);
    size_t comps = componentCount(a.type);
    if (out.componentSize == 0)
        return accessorError(index, "unknown componentType " + std::to_string(a.componentType));
    if (comps == 0) return accessorError(index, "unknown type");
    if (a.count > kMaxElements)
        return accessorError(index, "count " + std::to_string(a.count) + " is absurd (over 2^" +
                                        std::to_string(kMaxElementsLog2) + ")");
    if (a.bufferView == -1 && a.count > kMaxZeroFilled && !compressed)
        return accessorError(index, "has no bufferView yet declares " + std::to_string(a.count) +
                                        " elements (zeros; at most 2^" +
                                        std::to_string(kMaxZeroFilledLog2) +
                                        " without data in the file)");
    out.elementSize = out.componentSize * comps;
    out.stride = out.elementSize;
    if (compressed) return {}; // its data is in a Draco bitstream, never read through a view
    if (a.bufferView != -1 && a.count > 0) {
        if (a.bufferView >= 0 && size_t(a.bufferView) < model.bufferViews.size()) {
            size_t byteStride = model.bufferViews[size_t(a.bufferView)].byteStride;
            if (byteStride != 0 && (byteStride < out.elementSize || byteStride > 252))
                return accessorError(index, "byteStride " + std::to_string(byteStride) +
                                                " does not fit elements of " +
                                                std::to_string(out.elementSize) + " bytes");
            if (byteStride != 0) out.stride = byteStride;
        }
        uint64_t span = uint64_t(a.count - 1) * out.stride + out.elementSize;
        Status s = resolveView(model, index, a.bufferView, a.byteOffset, span, "", out.data);
        if (!s) return s;
    }
    if (!a.sparse.isSparse) return {};
    const auto& sp = a.sparse;
    if (sp.count < 1 || size_t(sp.count) > a.count)
        return accessorError(index, "sparse count " + std::to_string(sp.count) + " is outside 1.." +
                                        std::to_string(a.count));
    size_t indexSize = componentSize(sp.indices.componentType);
    if (indexSize == 0 || sp.indices.componentType == kByte || sp.indices.componentType == kShort ||
        sp.indices.componentType == kFloat)
        return accessorError(index, "sparse indices have componentType " +
                                        std::to_string(sp.indices.componentType) +
                                        " (must be an unsigned integer type)");
    if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0)
        return accessorError(index, "sparse byteOffset is negative");
    Status s = resolveView(model, index, sp.indices.bufferView, uint64_t(sp.indices.byteOffset),
                           uint64_t(sp.count) * indexSize, "sparse indices ", out.sparseIndices);
    if (!s) return s;
    return resolveView(model, index, sp.values.bufferView, uint64_t(sp.values.byteOffset),
                       uint64_t(sp.count) * out.elementSize, "sparse values ", out.sparseValues);
}

float decodeComponent(const uint8_t* p, int type, bool normalized) {
    switch (type) {
    case kByte: {
        int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
    }
    case kUByte:
        return normalized ? float(*p) / 255.0f : float(*p);
    case kShort: {
        int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    case kUShort: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? float(v) / 65535.0f : float(v);
    }
    case kUInt: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? float(double(v) / 4294967295.0) : float(v);
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

uint32_t decodeIndex(const uint8_t* p, int type) {
    if (type == kUByte) return *p;
    if (type == kUShort) {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

// The accessor's sparse substitutions, if any: apply(target element, its value's bytes) for
// each, every target checked against the count first.
template <class Apply>
Status applySparse(const tinygltf::Accessor& a, const Located& loc, const std::string& what,
                   Apply&& apply) {
    if (!loc.sparseIndices) return {};
    const size_t indexSize = componentSize(a.sparse.indices.componentType);
    for (size_t k = 0; k < size_t(a.sparse.count); ++k) {
        uint32_t target =
            decodeIndex(loc.sparseIndices + k * indexSize, a.sparse.indices.componentType);
        if (target >= a.count)
            return Error{what + ": sparse index " + std::to_string(target) + " is past its count " +
                         std::to_string(a.count)};
        apply(target, loc.sparseValues + k * loc.elementSize);
    }
    return {};
}

} // namespace

Status checkAccessor(const tinygltf::Model& model, size_t index, bool compressed) {
    Located loc;
    return locate(model, index, loc, compressed);
}

Status readFloats(const tinygltf::Model& model, int index, const AttributeSpec& spec,
                  std::vector<float>& out, size_t& comps, bool keepNonFinite) {
    Located loc;
    Status s = locate(model, size_t(index), loc);
    if (!s) return s;
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    std::string what = std::string(spec.name) + " accessor " + std::to_string(index);
    if (std::find(spec.types.begin(), spec.types.end(), a.type) == spec.types.end())
        return Error{what + " is " + typeName(a.type) + ", which " + spec.name + " cannot be"};
    if (std::find(spec.componentTypes.begin(), spec.componentTypes.end(), a.componentType) ==
        spec.componentTypes.end())
        return Error{what + " has componentType " + std::to_string(a.componentType) + ", which " +
                     spec.name + " cannot have"};
    comps = componentCount(a.type);
    bool normalized = a.normalized || spec.forceNormalized;
    out.assign(a.count * comps, 0.0f);
    auto decodeElement = [&](const uint8_t* src, float* dst) {
        if (a.componentType == kFloat) {
            std::memcpy(dst, src, comps * sizeof(float));
            return;
        }
        for (size_t c = 0; c < comps; ++c)
            dst[c] = decodeComponent(src + c * loc.componentSize, a.componentType, normalized);
    };
    if (loc.data) {
        for (size_t i = 0; i < a.count; ++i)
            decodeElement(loc.data + i * loc.stride, &out[i * comps]);
    }
    s = applySparse(a, loc, what, [&](uint32_t target, const uint8_t* value) {
        decodeElement(value, &out[target * comps]);
    });
    if (!s) return s;
    if (!keepNonFinite)
        for (float v : out)
            if (!std::isfinite(v)) return Error{what + " holds a NaN or infinite value"};
    return {};
}

Status readIndices(const tinygltf::Model& model, int index, size_t vertexCount,
                   std::vector<uint32_t>& out) {
    Located loc;
    Status s = locate(model, size_t(index), loc);
    if (!s) return s;
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    std::string what = "index accessor " + std::to_string(index);
    if (a.type != TINYGLTF_TYPE_SCALAR ||
        (a.componentType != kUByte && a.componentType != kUShort && a.componentType != kUInt))
        return Error{what + " must be SCALAR of unsigned byte, short or int"};
    out.assign(a.count, 0u);
    if (loc.data)
        for (size_t i = 0; i < a.count; ++i)
            out[i] = decodeIndex(loc.data + i * loc.stride, a.componentType);
    s = applySparse(a, loc, what, [&](uint32_t target, const uint8_t* value) {
        out[target] = decodeIndex(value, a.componentType);
    });
    if (!s) return s;
    for (size_t i = 0; i < out.size(); ++i)
        if (out[i] >= vertexCount)
            return Error{what + ": index " + std::to_string(out[i]) + " at position " +
                         std::to_string(i) + " is out of range (" + std::to_string(vertexCount) +
                         " vertices)"};
    return {};
}

} // namespace tp::gltf
