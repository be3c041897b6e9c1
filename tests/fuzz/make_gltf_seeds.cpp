// Writes the compressed and repaired scenes of tests/common/gltf_test_scenes.h (Draco from
// libdraco's encoder, meshopt from meshoptimizer's, attributes to repair, a texture transform)
// as self-contained GLB seeds for fuzz_gltf: buffer 0 becomes the BIN chunk, the texture a data
// URI. Without them the fuzzer would meet a valid Draco or meshopt stream only where
// ../shared/scenes happens to be present (Duck-Draco), and could not mutate one from scratch.
//
// Usage: make_gltf_seeds DIR   (writes DIR/generated_*.glb)
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>

#include <nlohmann/json.hpp>

#include "tests/common/gltf_test_scenes.h"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::vector<uint8_t> readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

std::string base64(const std::vector<uint8_t>& b) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < b.size(); i += 3) {
        const uint32_t v = uint32_t(b[i]) << 16 | (i + 1 < b.size() ? b[i + 1] << 8 : 0) |
                           (i + 2 < b.size() ? b[i + 2] : 0);
        for (size_t k = 0; k < 4; ++k)
            out += k <= b.size() - i ? abc[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

void put32(std::vector<uint8_t>& out, uint32_t v) {
    for (int s = 0; s < 32; s += 8)
        out.push_back(uint8_t(v >> s));
}

// scene.gltf + scene.bin + checker.png -> one GLB (glTF 2.0 spec, 4.4).
std::vector<uint8_t> toGlb(const fs::path& gltfPath) {
    const fs::path dir = gltfPath.parent_path();
    json g = json::parse(readAll(gltfPath));
    std::vector<uint8_t> bin = readAll(dir / g["buffers"][0]["uri"].get<std::string>());
    g["buffers"][0].erase("uri");
    for (json& image : g["images"])
        image["uri"] =
            "data:image/png;base64," + base64(readAll(dir / image["uri"].get<std::string>()));
    std::string text = g.dump();
    while (text.size() % 4)
        text += ' ';
    while (bin.size() % 4)
        bin.push_back(0);
    std::vector<uint8_t> out = {'g', 'l', 'T', 'F'};
    put32(out, 2);
    put32(out, uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    put32(out, uint32_t(text.size()));
    put32(out, 0x4E4F534Au);
    out.insert(out.end(), text.begin(), text.end());
    put32(out, uint32_t(bin.size()));
    put32(out, 0x004E4942u);
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_gltf_seeds DIR\n");
        return 2;
    }
    const fs::path out = argv[1], work = out / "make_gltf_seeds.tmp";
    tp::test::RepairCounts counts;
    const std::pair<const char*, std::function<fs::path(const fs::path&)>> scenes[] = {
        {"draco", tp::test::writeDracoScene},
        {"meshopt", tp::test::writeMeshoptScene},
        {"repair", [&](const fs::path& d) { return tp::test::writeRepairScene(d, counts); }},
        {"texture_transform", tp::test::writeTextureTransformScene},
    };
    for (const auto& [name, write] : scenes) {
        const std::vector<uint8_t> glb = toGlb(write(work / name));
        std::ofstream(out / (std::string("generated_") + name + ".glb"), std::ios::binary)
            .write(reinterpret_cast<const char*>(glb.data()), std::streamsize(glb.size()));
        std::printf("generated_%s.glb: %zu bytes\n", name, glb.size());
    }
    fs::remove_all(work);
    return 0;
}
