// tinygltf 2.7 refuses two things compressed glTF files contain: a meshopt fallback buffer
// without a uri, and a Draco primitive's index accessor without a bufferView. Before it
// parses, the JSON (of a .gltf, or the JSON chunk of a .glb) is rewritten to satisfy it.
#include <nlohmann/json.hpp>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {

using nlohmann::json;

namespace {

void appendLe32(std::vector<unsigned char>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(uint8_t(v >> (8 * i)));
}

// The patches of patchForTinygltf on the parsed JSON; true if anything changed.
bool patchJson(json& root) {
    bool changed = false;
    if (root.contains("buffers") && root["buffers"].is_array())
        for (json& buffer : root["buffers"]) {
            if (!buffer.is_object() || buffer.contains("uri")) continue;
            const json* ext = jsonMember(buffer, "extensions");
            ext = ext ? jsonMember(*ext, "EXT_meshopt_compression") : nullptr;
            const json* fallback = ext ? jsonMember(*ext, "fallback") : nullptr;
            if (!fallback || !fallback->is_boolean() || !fallback->get<bool>()) continue;
            buffer["uri"] = "data:application/octet-stream;base64,AA=="; // one zero byte
            buffer["byteLength"] = 1;
            changed = true;
        }
    if (!root.contains("accessors") || !root["accessors"].is_array()) return changed;
    json& accessors = root["accessors"];
    for (const json& mesh : jsonArray(root, "meshes"))
        for (const json& p : jsonArray(mesh, "primitives")) {
            const json* ext = jsonMember(p, "extensions");
            ext = ext ? jsonMember(*ext, "KHR_draco_mesh_compression") : nullptr;
            const json* indices = jsonMember(p, "indices");
            const json* view = ext ? jsonMember(*ext, "bufferView") : nullptr;
            if (!indices || !indices->is_number_unsigned() || !view ||
                !view->is_number_unsigned() || indices->get<uint64_t>() >= accessors.size())
                continue;
            json& a = accessors[indices->get<size_t>()];
            if (!a.is_object() || a.contains("bufferView")) continue;
            a["bufferView"] = *view;
            changed = true;
        }
    return changed;
}

} // namespace

Status patchForTinygltf(std::vector<unsigned char>& bytes, bool binary,
                        std::string_view& jsonText) {
    if (jsonText.find("EXT_meshopt_compression") == std::string_view::npos &&
        jsonText.find("KHR_draco_mesh_compression") == std::string_view::npos)
        return {};
    json root = json::parse(jsonText.begin(), jsonText.end(), nullptr, false);
    if (root.is_discarded() || !root.is_object()) return {}; // prescan says what is wrong
    if (!patchJson(root)) return {};
    std::string text = root.dump();
    if (!binary) {
        bytes.assign(text.begin(), text.end());
        jsonText = std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        return {};
    }
    // The GLB again, its JSON chunk replaced (checkGlb has checked the old layout).
    const uint64_t binStart = 20 + ((uint64_t(readLe32(&bytes[12])) + 3) & ~3ull);
    while (text.size() % 4)
        text.push_back(' ');
    const uint64_t rest = binStart < bytes.size() ? bytes.size() - binStart : 0;
    const uint64_t total = 12 + 8 + text.size() + rest;
    if (total >= (1ull << 32)) return Error{"file is over 4 GiB once its JSON is rewritten"};
    std::vector<unsigned char> glb(bytes.begin(), bytes.begin() + 8);
    appendLe32(glb, uint32_t(total));
    appendLe32(glb, uint32_t(text.size()));
    appendLe32(glb, 0x4E4F534Au);
    glb.insert(glb.end(), text.begin(), text.end());
    if (rest) glb.insert(glb.end(), bytes.begin() + int64_t(binStart), bytes.end());
    bytes.swap(glb);
    jsonText = std::string_view(reinterpret_cast<const char*>(&bytes[20]), text.size());
    return {};
}

} // namespace tp::gltf
