// KHR_draco_mesh_compression: a primitive's attributes and indices decoded by libdraco from
// one bufferView. The only file that includes Draco (STYLE.md, lesson 15).
#include <algorithm>
#include <cmath>
#include <limits>

#include <draco/compression/decode.h>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
namespace {

// Integer data the accessor marks normalized that Draco did not: to [0,1] or [-1,1], as
// readFloats does for plain accessors.
float normalizeScale(draco::DataType type) {
    switch (type) {
    case draco::DT_INT8:
        return 1.0f / 127.0f;
    case draco::DT_UINT8:
        return 1.0f / 255.0f;
    case draco::DT_INT16:
        return 1.0f / 32767.0f;
    case draco::DT_UINT16:
        return 1.0f / 65535.0f;
    default:
        return 1.0f;
    }
}

// The bufferView holding the bitstream, checked to lie inside its buffer.
Status findBitstream(const tinygltf::Model& model, int viewIndex,
                     const tinygltf::BufferView*& out) {
    if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
        return Error{"bufferView " + std::to_string(viewIndex) + " does not exist"};
    const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        return Error{"bufferView " + std::to_string(viewIndex) + " has no buffer"};
    const std::vector<unsigned char>& bytes = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > bytes.size() || view.byteLength > bytes.size() - view.byteOffset)
        return Error{"bufferView " + std::to_string(viewIndex) + " lies outside its buffer"};
    out = &view;
    return {};
}

// One attribute of `specs` as floats into out.attributes, when the extension lists it; its
// component count must be its accessor's.
Status readAttribute(const tinygltf::Model& model, const tinygltf::Primitive& p,
                     const draco::Mesh& mesh, const tinygltf::Value& attributes,
                     const AttributeSpec& spec, DracoPrimitive& out) {
    if (!attributes.Has(spec.name)) return {};
    const tinygltf::Value& id = attributes.Get(spec.name);
    const draco::PointAttribute* a =
        id.IsNumber() && id.GetNumberAsInt() >= 0
            ? mesh.GetAttributeByUniqueId(uint32_t(id.GetNumberAsInt()))
            : nullptr;
    if (!a) return Error{std::string(spec.name) + " names no attribute of the bitstream"};
    auto accessor = p.attributes.find(spec.name);
    if (accessor == p.attributes.end() || accessor->second < 0 ||
        size_t(accessor->second) >= model.accessors.size())
        return Error{std::string(spec.name) + " has no accessor in the primitive"};
    const tinygltf::Accessor& acc = model.accessors[size_t(accessor->second)];
    size_t comps = acc.type == TINYGLTF_TYPE_VEC2   ? 2
                   : acc.type == TINYGLTF_TYPE_VEC3 ? 3
                   : acc.type == TINYGLTF_TYPE_VEC4 ? 4
                                                    : 0;
    if (comps == 0 || a->num_components() != comps)
        return Error{std::string(spec.name) + " has " + std::to_string(a->num_components()) +
                     " components in the bitstream, its accessor another type"};
    const bool normalize = (acc.normalized || spec.forceNormalized) && !a->normalized();
    const float scale = normalize ? normalizeScale(a->data_type()) : 1.0f;
    std::vector<float>& values = out.attributes[spec.name];
    values.resize(out.points * comps);
    for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
        float* dst = &values[size_t(i.value()) * comps];
        if (!a->ConvertValue<float>(a->mapped_index(i), int8_t(comps), dst))
            return Error{std::string(spec.name) + " cannot be converted to floats"};
        for (size_t c = 0; c < comps; ++c)
            dst[c] = scale == 1.0f ? dst[c] : std::max(dst[c] * scale, -1.0f);
    }
    out.comps[spec.name] = comps;
    return {};
}

} // namespace

bool hasDraco(const tinygltf::Primitive& p) {
    return p.extensions.count("KHR_draco_mesh_compression") != 0;
}

Status decodeDraco(const tinygltf::Model& model, const tinygltf::Primitive& p,
                   const std::vector<AttributeSpec>& specs, DracoPrimitive& out) {
    const tinygltf::Value& ext = p.extensions.at("KHR_draco_mesh_compression");
    const std::string what = "KHR_draco_mesh_compression";
    if (!ext.IsObject() || !ext.Get("bufferView").IsNumber() || !ext.Get("attributes").IsObject())
        return Error{what + ": bufferView or attributes missing"};
    const tinygltf::BufferView* view = nullptr;
    if (Status v = findBitstream(model, ext.Get("bufferView").GetNumberAsInt(), view); !v)
        return Error{what + ": " + v.error()};
    const std::vector<unsigned char>& bytes = model.buffers[size_t(view->buffer)].data;

    // What the stream decodes to must match the counts its accessors declare (which
    // checkDeclaredSize bounded before anything was read).
    auto accessorCount = [&](int index) -> uint64_t {
        return index >= 0 && size_t(index) < model.accessors.size()
                   ? model.accessors[size_t(index)].count
                   : 0;
    };
    auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) return Error{what + ": no POSITION attribute"};
    const uint64_t points = accessorCount(position->second);

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes.data() + view->byteOffset), view->byteLength);
    auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!type.ok()) return Error{what + ": " + type.status().error_msg_string()};
    if (type.value() != draco::TRIANGULAR_MESH)
        return Error{what + ": the bitstream is not a triangle mesh"};
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) return Error{what + ": " + decoded.status().error_msg_string()};
    const draco::Mesh& mesh = *decoded.value();
    if (mesh.num_points() != points)
        return Error{what + ": the bitstream decodes to " + std::to_string(mesh.num_points()) +
                     " vertices, the POSITION accessor declares " + std::to_string(points)};
    if (p.indices >= 0 && uint64_t(mesh.num_faces()) * 3 != accessorCount(p.indices))
        return Error{what + ": the bitstream decodes to " + std::to_string(mesh.num_faces()) +
                     " triangles, the index accessor declares " +
                     std::to_string(accessorCount(p.indices)) + " indices"};
    out.points = mesh.num_points();
    out.indices.resize(size_t(mesh.num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int k = 0; k < 3; ++k)
            out.indices[size_t(f.value()) * 3 + size_t(k)] = mesh.face(f)[k].value();

    const tinygltf::Value& attributes = ext.Get("attributes");
    for (const AttributeSpec& spec : specs)
        if (Status r = readAttribute(model, p, mesh, attributes, spec, out); !r)
            return Error{what + ": " + r.error()};
    return {};
}

} // namespace tp::gltf
