// The hostile scenes: a valid one-triangle glTF broken one way per case. Each case names what
// the loader must mention; the numbers that overflow say in their comment what a 32-bit (or
// 64-bit) sum or product would have wrapped to.
#include "tests/cli/hostile_scenes.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

namespace tp::hostile {

// Three vertices (36 bytes of floats) and three uint16 indices (6 bytes, padded to 8).
std::vector<uint8_t> triangleBin() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const uint16_t indices[4] = {0, 1, 2, 0};
    std::vector<uint8_t> bin(44);
    std::memcpy(bin.data(), positions, 36);
    std::memcpy(bin.data() + 36, indices, 8);
    return bin;
}

nlohmann::json triangleJson() {
    return nlohmann::json::parse(R"({
      "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
         "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                      {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "buffers": [{"uri": "tri.bin", "byteLength": 44}]})");
}

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Bytes = std::vector<uint8_t>;

void put32(Bytes& b, size_t at, uint32_t v) {
    std::memcpy(b.data() + at, &v, 4); // GLB is little-endian, as is every machine we build on
}

Bytes makeGlb(json gltf, Bytes bin) {
    gltf["buffers"][0].erase("uri");
    gltf["buffers"][0]["byteLength"] = bin.size();
    std::string text = gltf.dump();
    while (text.size() % 4)
        text += ' ';
    while (bin.size() % 4)
        bin.push_back(0);
    Bytes out(12 + 8 + text.size() + 8 + bin.size());
    put32(out, 0, 0x46546C67u); // "glTF"
    put32(out, 4, 2);
    put32(out, 8, uint32_t(out.size()));
    put32(out, 12, uint32_t(text.size()));
    put32(out, 16, 0x4E4F534Au); // "JSON"
    std::memcpy(out.data() + 20, text.data(), text.size());
    const size_t binAt = 20 + text.size();
    put32(out, binAt, uint32_t(bin.size()));
    put32(out, binAt + 4, 0x004E4942u); // "BIN\0"
    std::memcpy(out.data() + binAt + 8, bin.data(), bin.size());
    return out;
}

uint32_t crc32(const uint8_t* p, size_t n) {
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k)
            c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return c ^ 0xFFFFFFFFu;
}

// A PNG whose header claims w x h (8-bit RGBA) followed by a few bytes of IDAT that are not
// the image: only a loader that trusts the header before decoding would allocate w*h*4.
Bytes pngClaiming(uint32_t w, uint32_t h) {
    Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    auto be32 = [&](uint32_t x) {
        for (int s = 24; s >= 0; s -= 8)
            png.push_back(uint8_t(x >> s));
    };
    auto chunk = [&](const char* type, const Bytes& data) {
        be32(uint32_t(data.size()));
        const size_t start = png.size();
        png.insert(png.end(), type, type + 4);
        png.insert(png.end(), data.begin(), data.end());
        be32(crc32(png.data() + start, png.size() - start));
    };
    Bytes ihdr;
    for (uint32_t x : {w, h})
        for (int s = 24; s >= 0; s -= 8)
            ihdr.push_back(uint8_t(x >> s));
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});
    chunk("IHDR", ihdr);
    chunk("IDAT", {0x78, 0x01, 0x03, 0x00, 0xde, 0xad, 0xbe, 0xef});
    chunk("IEND", {});
    return png;
}

Bytes text(const std::string& s) {
    return Bytes(s.begin(), s.end());
}

// `bytes` as a base64 data URI: a scene with it needs no file beside it (fuzz seeds).
std::string dataUri(const Bytes& bin) {
    static const char* kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const size_t n = bin.size();
    std::string uri = "data:application/octet-stream;base64,";
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = uint32_t(bin[i]) << 16;
        if (i + 1 < n) v |= uint32_t(bin[i + 1]) << 8;
        if (i + 2 < n) v |= bin[i + 2];
        uri += kAlphabet[v >> 18 & 63];
        uri += kAlphabet[v >> 12 & 63];
        uri += i + 1 < n ? kAlphabet[v >> 6 & 63] : '=';
        uri += i + 2 < n ? kAlphabet[v & 63] : '=';
    }
    return uri;
}

// A triangle whose material's base colour shows image 0 at `uri`.
json texturedTriangle(const json& images) {
    json g = triangleJson();
    g["images"] = images;
    g["textures"] = json::array();
    for (size_t i = 0; i < images.size(); ++i)
        g["textures"].push_back({{"source", i}});
    g["materials"] = json::array();
    for (size_t i = 0; i < images.size(); ++i)
        g["materials"].push_back(
            {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
    g["meshes"][0]["primitives"][0]["material"] = 0;
    // Every material used: one primitive per image, all on the same triangle.
    for (size_t i = 1; i < images.size(); ++i) {
        json p = g["meshes"][0]["primitives"][0];
        p["material"] = i;
        g["meshes"][0]["primitives"].push_back(p);
    }
    return g;
}

class Writer {
  public:
    explicit Writer(fs::path root) : root_(std::move(root)) {}

    // A case whose files are given as they are (relative path -> bytes); the scene is one of them.
    void files(Case c, const std::map<std::string, Bytes>& files) {
        const fs::path dir = root_ / c.name;
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (const auto& [rel, bytes] : files) {
            fs::create_directories((dir / rel).parent_path());
            std::ofstream(dir / rel, std::ios::binary)
                .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        }
        cases_.push_back(std::move(c));
    }
    // A .gltf with tri.bin beside it.
    void gltf(Case c, const json& g, const Bytes& bin = triangleBin()) {
        const std::string binPath = (fs::path(c.scene).parent_path() / "tri.bin").string();
        // Named before `c` is moved: clang evaluates the arguments left to right, so reading
        // c.scene in the call read a moved-from string (the fuzz seeds lost their scenes).
        const std::string scene = c.scene;
        files(std::move(c), {{scene, text(g.dump(1))}, {binPath, bin}});
    }
    std::vector<Case> done() { return std::move(cases_); }

  private:
    fs::path root_;
    std::vector<Case> cases_;
};

constexpr Expect E = Expect::Error;
constexpr Expect W = Expect::Warning;

void glbCases(Writer& w) {
    const Bytes glb = makeGlb(triangleJson(), triangleBin());
    const size_t jsonEnd = 20 + size_t(glb[12] | glb[13] << 8);
    auto cut = [&](size_t size, bool fixLength) {
        Bytes b(glb.begin(), glb.begin() + long(size));
        if (fixLength && size >= 12) put32(b, 8, uint32_t(size));
        return b;
    };
    w.files({"glb_empty", "scene.glb", E, "file is empty", "an empty .glb"}, {{"scene.glb", {}}});
    w.files({"glb_cut_in_header", "scene.glb", E, "12-byte GLB header", "7 bytes of a GLB"},
            {{"scene.glb", cut(7, false)}});
    w.files({"glb_cut_in_json", "scene.glb", E, "GLB header gives a length",
             "cut inside the JSON chunk, header length unchanged"},
            {{"scene.glb", cut(jsonEnd - 10, false)}});
    w.files({"glb_cut_in_json_length_patched", "scene.glb", E, "JSON chunk",
             "cut inside the JSON chunk, header length patched to match"},
            {{"scene.glb", cut(jsonEnd - 10, true)}});
    w.files({"glb_cut_in_bin", "scene.glb", E, "BIN chunk",
             "cut inside the BIN chunk, header length patched to match"},
            {{"scene.glb", cut(glb.size() - 8, true)}});
    Bytes hugeChunk = glb;
    put32(hugeChunk, 12, 0xFFFFFFF0u); // 20 + length wraps to 4 in 32 bits
    w.files({"glb_json_chunk_length_wraps", "scene.glb", E, "JSON chunk",
             "JSON chunk length 2^32-16: 20 + length wraps to 4 in 32-bit arithmetic"},
            {{"scene.glb", hugeChunk}});
}

void rangeCases(Writer& w) {
    json g = triangleJson();
    g["bufferViews"][1]["byteLength"] = 4000;
    w.gltf({"view_past_buffer", "scene.gltf", E, "outside its buffer",
            "a bufferView 4000 bytes long in a 44-byte buffer"},
           g);
    g = triangleJson();
    g["bufferViews"][0]["buffer"] = 7;
    w.gltf({"view_of_missing_buffer", "scene.gltf", E, "buffer 7",
            "a bufferView of buffer 7 (there is one)"},
           g);
    g = triangleJson();
    g["bufferViews"][1]["byteOffset"] = 4294967292ull; // + byteLength 6 wraps to 2 in 32 bits
    w.gltf({"view_offset_wraps_32bit", "scene.gltf", E, "outside its buffer",
            "bufferView byteOffset 2^32-4: offset + length wraps to 2 in 32 bits"},
           g);
    g = triangleJson();
    g["accessors"][0]["count"] = 0; // found by the fuzzer: memcpy from a null pointer (UB)
    w.gltf({"position_count_zero", "scene.gltf", E, "out of range (0 vertices)",
            "a POSITION accessor of count 0"},
           g);
    g = triangleJson();
    g["accessors"][0]["byteOffset"] = 40;
    w.gltf({"accessor_past_view", "scene.gltf", E, "lies outside bufferView",
            "an accessor starting 40 bytes into a 36-byte bufferView"},
           g);
    g = triangleJson();
    g["accessors"][0]["bufferView"] = 9;
    w.gltf({"accessor_of_missing_view", "scene.gltf", E, "bufferView 9 does not exist",
            "an accessor of bufferView 9 (there are two)"},
           g);
    g = triangleJson();
    g["accessors"][0]["count"] = 4294967299ull; // wraps to 3 in 32 bits: the true count
    w.gltf({"count_wraps_32bit", "scene.gltf", E, "is absurd",
            "POSITION count 2^32+3, which a 32-bit count reads as 3"},
           g);
    g = triangleJson();
    g["accessors"][0]["type"] = "VEC4";
    g["accessors"][0]["count"] = 268435457ull; // * 16 bytes = 2^32 + 16: wraps to 16
    w.gltf({"count_times_size_wraps_32bit", "scene.gltf", E, "is absurd",
            "count 2^28+1 of 16-byte elements: count * size wraps to 16 in 32 bits"},
           g);
    g = triangleJson();
    g["accessors"][1]["sparse"] = json::parse(R"({"count": 2147483648,
        "indices": {"bufferView": 1, "componentType": 5123},
        "values": {"bufferView": 1}})");
    w.gltf({"sparse_count_overflows", "scene.gltf", E, "sparse count",
            "sparse count 2^31 (a negative int) on a 3-element accessor"},
           g);
}

void indexCases(Writer& w) {
    Bytes bin = triangleBin();
    const uint16_t past[3] = {0, 1, 3};
    std::memcpy(bin.data() + 36, past, 6);
    w.gltf({"index_past_vertex_count", "scene.gltf", E, "index 3 at position 2 is out of range",
            "index 3 into 3 vertices"},
           triangleJson(), bin);
    json g = triangleJson();
    const uint32_t restart[3] = {0, 1, 0xFFFFFFFFu};
    bin = triangleBin();
    bin.resize(36);
    bin.insert(bin.end(), reinterpret_cast<const uint8_t*>(restart),
               reinterpret_cast<const uint8_t*>(restart) + 12);
    g["bufferViews"][1]["byteLength"] = 12;
    g["accessors"][1]["componentType"] = 5125;
    g["buffers"][0]["byteLength"] = bin.size();
    w.gltf({"index_0xffffffff", "scene.gltf", E, "index 4294967295",
            "uint32 index 2^32-1 (a restart value or a -1)"},
           g, bin);
}

void uriCases(Writer& w) {
    json g = triangleJson();
    g["buffers"][0]["uri"] = "../../etc/passwd";
    w.gltf({"buffer_uri_etc_passwd", "scene.gltf", E, "leaves the scene's folder",
            "buffer URI ../../etc/passwd"},
           g);
    // The file it points to exists and is a valid buffer: only the path makes it wrong.
    g["buffers"][0]["uri"] = "../../tri.bin";
    w.files({"buffer_uri_escapes_to_a_real_file", "a/b/scene.gltf", E, "leaves the scene's folder",
             "buffer URI ../../tri.bin, a valid buffer outside"},
            {{"a/b/scene.gltf", text(g.dump(1))}, {"tri.bin", triangleBin()}});
    g["buffers"][0]["uri"] = "%2e%2e/%2e%2e/etc/passwd";
    w.gltf({"buffer_uri_percent_encoded_escape", "scene.gltf", E, "leaves the scene's folder",
            "buffer URI %2e%2e/%2e%2e/etc/passwd"},
           g);
    g["buffers"][0]["uri"] = "/etc/passwd";
    w.gltf({"buffer_uri_absolute", "scene.gltf", E, "absolute path", "buffer URI /etc/passwd"}, g);
    g["buffers"][0]["uri"] = "file:///etc/passwd";
    w.gltf({"buffer_uri_file_scheme", "scene.gltf", E, "has a scheme",
            "buffer URI file:///etc/passwd"},
           g);
    g["buffers"][0]["uri"] = "data:application/octet-stream,AAAAAAAAAAAA";
    w.gltf({"buffer_data_uri_not_base64", "scene.gltf", E, "only base64 data URIs",
            "a data URI without ;base64"},
           g);
    g["buffers"][0]["uri"] =
        "data:application/octet-stream;base64,!!!!****~~~~" + std::string(44, '@');
    w.gltf({"buffer_data_uri_bad_base64", "scene.gltf", E, "not base64 at offset",
            "a ;base64 data URI of characters outside the base64 alphabet"},
           g);
}

void textureCases(Writer& w) {
    w.gltf({"texture_missing", "scene.gltf", W, "missing.png': file not found; using a placeholder",
            "base colour texture missing.png is not there"},
           texturedTriangle(json::parse(R"([{"uri": "missing.png"}])")));
    w.gltf({"texture_uri_etc_passwd", "scene.gltf", W, "leaves the scene's folder",
            "image URI ../../etc/passwd"},
           texturedTriangle(json::parse(R"([{"uri": "../../etc/passwd"}])")));
    json g = texturedTriangle(json::parse(R"([{"uri": "huge.png"}])"));
    w.files({"texture_100000x100000_header", "scene.gltf", E, "100000x100000, over the 16384 limit",
             "a 72-byte PNG whose header claims 100,000 x 100,000 (40 GB as RGBA8)"},
            {{"scene.gltf", text(g.dump(1))},
             {"tri.bin", triangleBin()},
             {"huge.png", pngClaiming(100000, 100000)}});
    g = texturedTriangle(json::parse(R"([{"uri": "a.png"}, {"uri": "b.png"}])"));
    w.files({"textures_over_pixel_budget", "scene.gltf", E, "add up to",
             "two PNG headers of 16384 x 16384 each: 2^29 pixels together"},
            {{"scene.gltf", text(g.dump(1))},
             {"tri.bin", triangleBin()},
             {"a.png", pngClaiming(16384, 16384)},
             {"b.png", pngClaiming(16384, 16384)}});
    g = texturedTriangle(json::parse(R"([{"uri": "broken.png"}])"));
    w.files({"texture_header_lies", "scene.gltf", W, "cannot decode",
             "a 64 x 64 PNG header in front of bytes that are not its image"},
            {{"scene.gltf", text(g.dump(1))},
             {"tri.bin", triangleBin()},
             {"broken.png", pngClaiming(64, 64)}});
    g = texturedTriangle(json::parse(R"([{"uri": "data:image/png;base64,%%%%"}])"));
    w.gltf({"texture_data_uri_bad_base64", "scene.gltf", E,
            "image 0: the data URI holds a character",
            "an image data URI of characters outside the base64 alphabet"},
           g);
    g = texturedTriangle(json::parse(R"([{"uri": "data:image/webp;base64,AAAA"}])"));
    w.gltf({"texture_data_uri_unknown_type", "scene.gltf", W, "image 0",
            "an image data URI of a type glTF does not allow (webp)"},
           g);
}

void zeroFillCases(Writer& w) {
    json g = triangleJson();
    g["accessors"][0].erase("bufferView");
    g["accessors"][0]["count"] = 1 << 24;
    w.gltf({"zero_positions_2e24", "scene.gltf", E, "has no bufferView",
            "POSITION of 2^24 zero vertices (no bufferView): 200 bytes asking for 192 MiB+"},
           g);
    g = triangleJson();
    g["accessors"][1].erase("bufferView");
    g["accessors"][1]["count"] = (1 << 20) + 3;
    // tinygltf refuses index accessors without a bufferView itself.
    w.gltf({"zero_indices", "scene.gltf", E, "accessor[1] invalid bufferView",
            "an index accessor of 2^20+3 zeros"},
           g);
    g = triangleJson();
    g["accessors"].push_back({{"componentType", 5126}, {"count", 1 << 20}, {"type", "VEC3"}});
    g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    w.gltf({"zero_normals_count_mismatch", "scene.gltf", E,
            "NORMAL has 1048576 elements but POSITION has 3",
            "NORMAL of 2^20 zeros on a 3-vertex primitive"},
           g);
    // 2^20 zero vertices are allowed; 32 nodes showing them are 2^25 vertices.
    g = triangleJson();
    g["accessors"][0].erase("bufferView");
    g["accessors"][0]["count"] = 1 << 20;
    g["meshes"][0]["primitives"][0].erase("indices");
    g["nodes"] = json::array();
    g["scenes"][0]["nodes"] = json::array();
    for (int i = 0; i < 32; ++i) {
        g["nodes"].push_back({{"mesh", 0}});
        g["scenes"][0]["nodes"].push_back(i);
    }
    w.gltf({"instancing_bomb", "scene.gltf", E, "absurdly large",
            "one mesh of 2^20 zero vertices on 32 nodes: 2^25 vertices placed"},
           g);
}

void fileCases(Writer& w) {
    w.files({"gltf_empty", "scene.gltf", E, "file is empty", "an empty .gltf"},
            {{"scene.gltf", {}}});
    w.files({"scene_is_a_directory", "scene.gltf", E, "not a regular file",
             "a directory named scene.gltf"},
            {{"scene.gltf/placeholder", {}}});
    w.files({"not_gltf_at_all", "scene.gltf", E, "malformed JSON", "a PNG named scene.gltf"},
            {{"scene.gltf", pngClaiming(4, 4)}});
    w.files({"json_nested_100000_deep", "scene.gltf", E, "nested deeper",
             "100,000 nested arrays in extras (a recursive parser's stack)"},
            {{"scene.gltf", text(R"({"asset":{"version":"2.0","extras":)" +
                                 std::string(100000, '[') + std::string(100000, ']') + "}}")}});
    json g = triangleJson();
    g["extensionsUsed"] = {"EXT_made_up"};
    g["extensionsRequired"] = {"EXT_made_up"};
    w.gltf({"required_extension_unsupported", "scene.gltf", E, "requires extension EXT_made_up",
            "extensionsRequired: EXT_made_up"},
           g);
    g = triangleJson();
    g["asset"]["version"] = "1.0";
    w.gltf({"gltf_version_1", "scene.gltf", E, "only glTF 2.0", "asset.version 1.0"}, g);
}

} // namespace

// Non-finite attributes (repaired with a warning, positions refused) and compressed data that
// is garbage (refused with the extension's name).
void repairAndCompressedCases(Writer& w) {
    auto withAttribute = [](const char* name, const char* type, const std::vector<float>& values,
                            json& g, Bytes& bin) {
        const size_t offset = bin.size();
        bin.resize(offset + values.size() * 4);
        std::memcpy(bin.data() + offset, values.data(), values.size() * 4);
        g["buffers"][0]["byteLength"] = bin.size();
        g["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * 4}});
        g["accessors"].push_back({{"bufferView", g["bufferViews"].size() - 1},
                                  {"componentType", 5126},
                                  {"count", 3},
                                  {"type", type}});
        g["meshes"][0]["primitives"][0]["attributes"][name] = g["accessors"].size() - 1;
    };
    const float nan = std::nanf(""), inf = INFINITY;
    json g = triangleJson();
    Bytes bin = triangleBin();
    withAttribute("NORMAL", "VEC3", {nan, 0, 1, 0, 0, 1, 0, 0, 0}, g, bin);
    w.gltf({"nan_normals", "scene.gltf", W, "repaired NORMAL accessor 2: 2 of 3",
            "a NaN and a zero-length normal (repaired with the face normal)"},
           g, bin);
    g = triangleJson();
    bin = triangleBin();
    withAttribute("TEXCOORD_0", "VEC2", {0, 0, inf, 1, 1, nan}, g, bin);
    withAttribute("TANGENT", "VEC4", {1, 0, 0, 1, nan, 0, 0, 1, 1, 0, 0, inf}, g, bin);
    w.gltf({"nan_uvs_and_tangents", "scene.gltf", W, "repaired TEXCOORD_0 accessor 2: 2 of 3",
            "infinite and NaN uvs, NaN tangent xyz and infinite w (repaired)"},
           g, bin);
    bin = triangleBin();
    const float position = nan;
    std::memcpy(bin.data() + 16, &position, 4);
    w.gltf({"nan_position", "scene.gltf", E, "POSITION accessor 0 holds a NaN",
            "a NaN position (the geometry is unknowable: refused)"},
           triangleJson(), bin);

    // 36 bytes of triangleBin()'s positions read as a Draco bitstream.
    g = triangleJson();
    g["accessors"][0].erase("bufferView");
    g["accessors"][1].erase("bufferView");
    g["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", 0}, {"attributes", {{"POSITION", 0}}}};
    g["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    g["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    w.gltf({"draco_garbage", "scene.gltf", E, "KHR_draco_mesh_compression",
            "a Draco primitive whose bitstream is 36 bytes of floats"},
           g);
    bin = triangleBin();
    const char draco[] = "DRACO\x02\x02\x01\x01\x00";
    std::memcpy(bin.data(), draco, 10); // a valid header, then the floats: truncated
    w.gltf({"draco_truncated", "scene.gltf", E, "KHR_draco_mesh_compression",
            "a Draco header (2.2, edgebreaker) followed by 26 bytes of floats"},
           g, bin);

    // The positions' view meshopt-compressed, its bytes the plain floats: not meshopt data.
    g = triangleJson();
    g["buffers"].push_back(
        {{"byteLength", 36}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    g["bufferViews"][0] = {{"buffer", 1},
                           {"byteLength", 36},
                           {"byteStride", 12},
                           {"extensions",
                            {{"EXT_meshopt_compression",
                              {{"buffer", 0},
                               {"byteLength", 36},
                               {"byteStride", 12},
                               {"count", 3},
                               {"mode", "ATTRIBUTES"}}}}}};
    g["extensionsUsed"] = {"EXT_meshopt_compression"};
    g["extensionsRequired"] = {"EXT_meshopt_compression"};
    w.gltf({"meshopt_garbage", "scene.gltf", E, "EXT_meshopt_compression",
            "a meshopt ATTRIBUTES view whose bytes are plain floats"},
           g);
    // A valid meshopt triangle with a NaN normal: decoded, then repaired (a seed for the fuzzer).
    {
        json v = triangleJson();
        Bytes b = triangleBin();
        std::vector<uint8_t> encoded(meshopt_encodeVertexBufferBound(3, 12));
        encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), b.data(), 3, 12));
        const size_t offset = b.size();
        b.insert(b.end(), encoded.begin(), encoded.end());
        v["buffers"][0]["byteLength"] = b.size();
        v["buffers"].push_back(
            {{"byteLength", 36},
             {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
        v["bufferViews"][0] = {{"buffer", 1},
                               {"byteLength", 36},
                               {"byteStride", 12},
                               {"extensions",
                                {{"EXT_meshopt_compression",
                                  {{"buffer", 0},
                                   {"byteOffset", offset},
                                   {"byteLength", encoded.size()},
                                   {"byteStride", 12},
                                   {"count", 3},
                                   {"mode", "ATTRIBUTES"}}}}}};
        while (b.size() % 4)
            b.push_back(0);
        withAttribute("NORMAL", "VEC3", {0, 0, 1, nan, nan, nan, 0, 0, 1}, v, b);
        v["extensionsUsed"] = {"EXT_meshopt_compression"};
        v["extensionsRequired"] = {"EXT_meshopt_compression"};
        v["buffers"][0]["uri"] =
            dataUri(b); // self-contained: every case's tri.bin is one file to the fuzzer
        w.gltf({"meshopt_triangle_nan_normal", "scene.gltf", W,
                "repaired NORMAL accessor 2: 1 of 3",
                "a meshopt-compressed triangle (valid) with a NaN normal"},
               v, b);
    }
    g["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 1 << 24;
    g["bufferViews"][0]["byteLength"] = 12 << 24;
    w.gltf({"meshopt_count_bomb", "scene.gltf", E, "cannot hold",
            "a meshopt view of 36 compressed bytes declaring 2^24 vertices (192 MiB)"},
           g);
}

std::vector<Case> writeHostileScenes(const fs::path& root) {
    fs::create_directories(root);
    Writer w(root);
    fileCases(w);
    glbCases(w);
    rangeCases(w);
    indexCases(w);
    uriCases(w);
    textureCases(w);
    zeroFillCases(w);
    repairAndCompressedCases(w);
    return w.done();
}

std::vector<uint8_t> validTriangleGltf() {
    json g = triangleJson();
    g["buffers"][0]["uri"] = dataUri(triangleBin());
    return text(g.dump());
}

std::vector<uint8_t> validTriangleGlb() {
    return makeGlb(triangleJson(), triangleBin());
}

} // namespace tp::hostile
