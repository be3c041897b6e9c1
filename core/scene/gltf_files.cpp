// Everything glTF loading does with files, checked before tinygltf 2.7 (which trusts them)
// sees them: the file itself, the GLB container, the JSON (asset.version, extensionsRequired)
// and every buffer and image URI. tinygltf then reaches the disk only through callbacks that
// open the files the pre-scan allowed.
#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// tinygltf's own decoding (dlib::urldecode, '+' included), so that what is checked here is the
// path tinygltf then asks for.
std::string urlDecode(const std::string& s) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;
    };
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '+') {
            out += ' ';
        } else if (s[i] == '%' && i + 2 < s.size()) {
            out += char(hex(s[i + 1]) << 4 | hex(s[i + 2]));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

bool isDataUri(const std::string& uri) {
    return uri.rfind("data:", 0) == 0;
}

// The data URIs tinygltf 2.7 decodes (any other "data:" URI it takes for a file name).
const char* const kDataUriPrefixes[] = {"data:application/octet-stream;base64,",
                                        "data:application/gltf-buffer;base64,",
                                        "data:image/jpeg;base64,",
                                        "data:image/png;base64,",
                                        "data:image/bmp;base64,",
                                        "data:image/gif;base64,",
                                        "data:text/plain;base64,"};

bool decodableDataUri(const std::string& uri) {
    for (const char* p : kDataUriPrefixes)
        if (uri.rfind(p, 0) == 0) return true;
    return false;
}

// What is wrong with the base64 payload of a data URI tinygltf decodes ("" if nothing);
// `bytes` receives the decoded size. tinygltf stops silently at the first character outside
// the alphabet and fails the whole file when nothing decodes, so both are checked here.
std::string base64Problem(const std::string& uri, uint64_t& bytes) {
    const size_t start = uri.find(',') + 1;
    size_t end = uri.size();
    for (int pad = 0; pad < 2 && end > start && uri[end - 1] == '='; ++pad)
        --end;
    for (size_t i = start; i < end; ++i)
        if (!std::isalnum(uint8_t(uri[i])) && uri[i] != '+' && uri[i] != '/')
            return "the data URI holds a character that is not base64 at offset " +
                   std::to_string(i);
    const size_t chars = end - start;
    if (chars % 4 == 1 || chars == 0) return "the data URI's base64 is empty or truncated";
    bytes = chars / 4 * 3 + (chars % 4 == 0 ? 0 : chars % 4 - 1);
    return "";
}

// A buffer's data URI: one tinygltf decodes, valid base64, exactly byteLength bytes.
Status checkBufferDataUri(const std::string& uri, const json& buffer, const std::string& label) {
    if (!decodableDataUri(uri))
        return Error{label + ": only base64 data URIs are supported "
                             "(data:application/octet-stream;base64,...)"};
    uint64_t bytes = 0;
    if (std::string problem = base64Problem(uri, bytes); !problem.empty())
        return Error{label + ": " + problem};
    const json* length =
        buffer.is_object() && buffer.contains("byteLength") ? &buffer["byteLength"] : nullptr;
    if (length && length->is_number_unsigned() && length->get<uint64_t>() != bytes)
        return Error{label + ": the data URI holds " + std::to_string(bytes) +
                     " bytes, byteLength says " + std::to_string(length->get<uint64_t>())};
    return {};
}

// Empty when `uri` is a relative reference that stays inside `folder` (then `resolved` is the
// file's absolute path), else what is wrong with it. The check is lexical: a symbolic link
// inside the folder is trusted wherever it points.
std::string uriProblem(const std::string& uri, const fs::path& folder, fs::path& resolved) {
    size_t colon = uri.find(':');
    if (colon != std::string::npos && colon > 0 && std::isalpha(uint8_t(uri[0]))) {
        bool scheme = true;
        for (size_t i = 1; i < colon; ++i)
            scheme &=
                std::isalnum(uint8_t(uri[i])) || uri[i] == '+' || uri[i] == '-' || uri[i] == '.';
        if (scheme) return "has a scheme (" + uri.substr(0, colon + 1) + ")";
    }
    std::string path = urlDecode(uri);
    if (path.empty()) return "is empty";
    if (path.find('\0') != std::string::npos) return "contains a NUL byte";
    if (path[0] == '/' || path[0] == '\\') return "is an absolute path";
    resolved = (folder / path).lexically_normal();
    fs::path relative = resolved.lexically_relative(folder);
    if (relative.empty() || *relative.begin() == "..") return "leaves the scene's folder";
    return "";
}

// tinygltf reaches the disk only through these callbacks, which open nothing that
// FileAccess::allowed does not list. tinygltf also looks for a missing file in the working
// directory ("./uri"): not in the list, so not found.
std::string accessKey(const std::string& path) {
    return fs::path(path).lexically_normal().string();
}

bool fileExistsCb(const std::string& path, void* user) {
    std::error_code ec;
    return static_cast<FileAccess*>(user)->allowed.count(accessKey(path)) &&
           fs::is_regular_file(path, ec);
}

// Paths are used as they are: no ~ or $VAR expansion.
std::string expandFilePathCb(const std::string& path, void*) {
    return path;
}

bool readWholeFileCb(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
    auto* access = static_cast<FileAccess*>(user);
    auto it = access->allowed.find(accessKey(path));
    if (it == access->allowed.end()) {
        if (err) *err += "not a file of this scene: " + path + "\n";
        return false;
    }
    std::error_code ec;
    uint64_t size = fs::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    if (ec || !in) {
        if (err) *err += "cannot read " + path + "\n";
        return false;
    }
    // A .bin longer than its byteLength is read up to byteLength (tinygltf wants them equal).
    if (it->second != 0 && size > it->second) size = it->second;
    out->resize(size);
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        if (err) *err += "cannot read " + path + "\n";
        return false;
    }
    return true;
}

bool writeWholeFileCb(std::string* err, const std::string&, const std::vector<unsigned char>&,
                      void*) {
    if (err) *err += "writing is disabled\n";
    return false;
}

// Keeps the encoded bytes: images are decoded later, only those a material uses, in parallel
// (gltf_materials.cpp).
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// Fully supported extensions; any other one in extensionsRequired is an error.
const char* const kSupportedExtensions[] = {
    "KHR_materials_emissive_strength", "KHR_lights_punctual",     "KHR_mesh_quantization",
    "KHR_draco_mesh_compression",      "EXT_meshopt_compression", "KHR_texture_transform"};

Status checkAssetAndExtensions(const json& root, const WarnFn& warn) {
    const json* asset = jsonMember(root, "asset");
    const json* version = asset ? jsonMember(*asset, "version") : nullptr;
    if (!version || !version->is_string()) return Error{"asset.version is missing"};
    std::string v = version->get<std::string>();
    if (v.substr(0, v.find('.')) != "2")
        return Error{"asset.version is \"" + v + "\"; only glTF 2.0 is supported"};
    auto supported = [](const std::string& name) {
        for (const char* s : kSupportedExtensions)
            if (name == s) return true;
        return false;
    };
    std::string unsupported;
    for (const json& e : jsonArray(root, "extensionsRequired")) {
        std::string name = e.is_string() ? e.get<std::string>() : e.dump();
        if (!supported(name)) unsupported += (unsupported.empty() ? "" : ", ") + name;
    }
    if (!unsupported.empty())
        return Error{"requires extension " + unsupported + ", which this loader does not support"};
    std::string ignored;
    for (const json& e : jsonArray(root, "extensionsUsed"))
        if (e.is_string() && !supported(e.get<std::string>()))
            ignored += (ignored.empty() ? "" : ", ") + e.get<std::string>();
    if (!ignored.empty()) warn("ignoring extension " + ignored + " (used, not required)");
    return {};
}

uint64_t unsignedMember(const json& object, const char* key, uint64_t fallback) {
    const json* m = jsonMember(object, key);
    return m && m->is_number_unsigned() ? m->get<uint64_t>() : fallback;
}

// Buffers: every external one must be a readable file in the folder holding at least
// byteLength bytes. Images: a problem there is a placeholder later, so it is only recorded.
Status prescanUris(const json& root, const fs::path& folder, bool binary, FileAccess& access,
                   std::vector<std::string>& imageProblems) {
    const json& buffers = jsonArray(root, "buffers");
    for (size_t i = 0; i < buffers.size(); ++i) {
        std::string label = "buffer " + std::to_string(i);
        const json* uri = jsonMember(buffers[i], "uri");
        if (!uri) {
            if (binary) continue; // the GLB's BIN chunk
            return Error{label + " has no uri"};
        }
        if (!uri->is_string()) return Error{label + ": uri is not a string"};
        std::string text = uri->get<std::string>();
        if (isDataUri(text)) {
            if (Status s = checkBufferDataUri(text, buffers[i], label); !s) return s;
            continue;
        }
        label += " '" + text + "'";
        fs::path resolved;
        if (std::string problem = uriProblem(text, folder, resolved); !problem.empty())
            return Error{label + ": the URI " + problem + "; refusing to read it"};
        const json* length = jsonMember(buffers[i], "byteLength");
        if (!length || !length->is_number_unsigned())
            return Error{label + ": byteLength is missing or not a whole number"};
        uint64_t byteLength = length->get<uint64_t>();
        std::error_code ec;
        if (!fs::is_regular_file(resolved, ec)) return Error{label + ": file not found"};
        uint64_t size = fs::file_size(resolved, ec);
        if (ec || size == 0) return Error{label + ": file is empty or unreadable"};
        if (size < byteLength)
            return Error{label + ": file is truncated (" + std::to_string(size) +
                         " bytes, byteLength says " + std::to_string(byteLength) + ")"};
        access.allowed[resolved.string()] = byteLength;
    }

    const json& images = jsonArray(root, "images");
    const json& views = jsonArray(root, "bufferViews");
    imageProblems.assign(images.size(), "");
    for (size_t i = 0; i < images.size(); ++i) {
        if (const json* view = jsonMember(images[i], "bufferView")) {
            // tinygltf hands &buffer.data[view.byteOffset] to the image loader unchecked.
            uint64_t v = view->is_number_unsigned() ? view->get<uint64_t>() : UINT64_MAX;
            std::string label = "image " + std::to_string(i) + ": bufferView";
            if (v >= views.size()) return Error{label + " does not exist"};
            uint64_t b = unsignedMember(views[v], "buffer", UINT64_MAX);
            if (b >= buffers.size()) return Error{label + "'s buffer does not exist"};
            uint64_t offset = unsignedMember(views[v], "byteOffset", 0);
            uint64_t length = unsignedMember(views[v], "byteLength", UINT64_MAX);
            uint64_t bufferLength = unsignedMember(buffers[b], "byteLength", 0);
            if (offset > bufferLength || length > bufferLength - offset)
                return Error{label + " lies outside its buffer"};
            continue;
        }
        const json* uri = jsonMember(images[i], "uri");
        if (!uri || !uri->is_string()) continue;
        std::string text = uri->get<std::string>();
        if (decodableDataUri(text)) {
            // tinygltf fails the whole file on an image URI it cannot decode.
            uint64_t bytes = 0;
            if (std::string problem = base64Problem(text, bytes); !problem.empty())
                return Error{"image " + std::to_string(i) + ": " + problem};
            continue;
        }
        if (isDataUri(text)) continue; // a type tinygltf does not decode: a placeholder later
        fs::path resolved;
        if (std::string problem = uriProblem(text, folder, resolved); !problem.empty()) {
            imageProblems[i] = "the URI " + problem + "; refusing to read it";
            continue;
        }
        std::error_code ec;
        if (!fs::is_regular_file(resolved, ec))
            imageProblems[i] = "file not found";
        else if (fs::file_size(resolved, ec) == 0 || ec)
            imageProblems[i] = "file is empty"; // tinygltf would fail the whole load on it
        else
            access.allowed[resolved.string()] = 0;
    }
    return {};
}

// tinygltf 2.7 turns extras and extensions into tinygltf::Value recursively: deep enough
// nesting overflows the stack. Real glTF nests a handful of levels.
constexpr int kMaxJsonDepth = 256;

int jsonDepth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool inString = false, escaped = false;
    for (char c : text) {
        if (inString) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            deepest = std::max(deepest, ++depth);
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
    return deepest;
}

Status parseJson(std::string_view text, json& root) {
    if (jsonDepth(text) > kMaxJsonDepth)
        return Error{"malformed glTF: JSON nested deeper than " + std::to_string(kMaxJsonDepth) +
                     " levels"};
    try {
        root = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        std::string what = e.what();
        if (size_t bracket = what.find("] ");
            what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
            what = what.substr(bracket + 2);
        return Error{"malformed JSON: " + firstLine(what)};
    }
    if (!root.is_object()) return Error{"malformed glTF: the JSON root is not an object"};
    return {};
}

} // namespace

Status readFile(const std::string& path, std::vector<unsigned char>& bytes) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return Error{"file not found"};
    if (!fs::is_regular_file(path, ec)) return Error{"not a regular file"};
    uint64_t size = fs::file_size(path, ec);
    if (ec) return Error{"cannot read its size: " + ec.message()};
    if (size == 0) return Error{"file is empty"};
    if (size >= (1ull << 32)) return Error{"file is over 4 GiB, which tinygltf cannot load"};
    std::ifstream in(path, std::ios::binary);
    bytes.resize(size);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        return Error{"cannot read the file"};
    return {};
}

Status checkGlb(const std::vector<unsigned char>& b, std::string_view& jsonText) {
    const size_t size = b.size();
    if (size < 12) return Error{"file ends inside the 12-byte GLB header"};
    if (std::memcmp(b.data(), "glTF", 4) != 0) return Error{"not a GLB file (magic is not 'glTF')"};
    if (readLe32(&b[4]) != 2)
        return Error{"GLB version " + std::to_string(readLe32(&b[4])) + " is not supported"};
    if (readLe32(&b[8]) != size)
        return Error{"GLB header gives a length of " + std::to_string(readLe32(&b[8])) +
                     " bytes but the file has " + std::to_string(size)};
    if (size < 20) return Error{"file ends inside the JSON chunk header"};
    const uint64_t jsonLength = readLe32(&b[12]);
    if (readLe32(&b[16]) != 0x4E4F534Au) return Error{"the first GLB chunk is not JSON"};
    if (jsonLength == 0 || 20 + jsonLength > size)
        return Error{"the JSON chunk (" + std::to_string(jsonLength) +
                     " bytes) does not fit in the file"};
    const uint64_t binStart = 20 + ((jsonLength + 3) & ~3ull);
    if (binStart < size) {
        if (binStart + 8 > size) return Error{"file ends inside the BIN chunk header"};
        const uint64_t binLength = readLe32(&b[binStart]);
        if (binStart + 8 + binLength > size)
            return Error{"the BIN chunk (" + std::to_string(binLength) +
                         " bytes) runs past the end of the file"};
    }
    jsonText = std::string_view(reinterpret_cast<const char*>(&b[20]), size_t(jsonLength));
    return {};
}

Status prescan(std::string_view jsonText, const fs::path& folder, bool binary, FileAccess& access,
               std::vector<std::string>& imageProblems, const WarnFn& warn) {
    json root;
    if (Status s = parseJson(jsonText, root); !s) return s;
    if (Status s = checkAssetAndExtensions(root, warn); !s) return s;
    return prescanUris(root, folder, binary, access, imageProblems);
}

void confine(tinygltf::TinyGLTF& loader, FileAccess& access) {
    loader.SetFsCallbacks(
        {&fileExistsCb, &expandFilePathCb, &readWholeFileCb, &writeWholeFileCb, &access});
    loader.SetImageLoader(&keepEncodedImage, nullptr);
}

std::string firstLine(const std::string& text) {
    size_t begin = 0;
    while (begin < text.size()) {
        size_t end = std::min(text.find('\n', begin), text.size());
        std::string line = text.substr(begin, end - begin);
        line.erase(0, line.find_first_not_of(" \t\r"));
        line.erase(line.find_last_not_of(" \t\r") + 1);
        if (!line.empty()) return line;
        begin = end + 1;
    }
    return "";
}

// Shared with gltf_patch.cpp (declared in gltf_internal.h).
uint32_t readLe32(const unsigned char* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

const json* jsonMember(const json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const json& jsonArray(const json& root, const char* key) {
    static const json kEmpty = json::array();
    const json* a = jsonMember(root, key);
    return a && a->is_array() ? *a : kEmpty;
}

} // namespace tp::gltf
