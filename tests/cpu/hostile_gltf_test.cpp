// The glTF loader against hostile scenes (tests/cli/hostile_scenes.h): each is loaded in a
// child process with its address space capped, so a loader that believed a header or a count
// would fail there (or be killed) instead of taking the machine's memory; the child's peak
// resident memory is checked too. The CLI runs the same cases end to end
// (tests/cli/hostile_input.sh).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include "core/scene/gltf_internal.h"
#include "core/scene/gltf_loader.h"
#include "tests/cli/hostile_scenes.h"

namespace fs = std::filesystem;
using namespace tp;

namespace {

struct Outcome {
    bool exited = false; // false: the child died (a crash, or killed for memory)
    int signal = 0;
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    long peakRssKiB = 0;
};

size_t virtualBytesNow() {
    unsigned long pages = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%lu", &pages) != 1) pages = 0;
        std::fclose(f);
    }
    return size_t(pages) * size_t(sysconf(_SC_PAGESIZE));
}

// The address space the child may add to what it inherits: the decoder threads' stacks and
// the largest legitimate allocation of these tiny scenes fit many times over; 40 GB (or the
// 1-2 GiB a believed count asks for) do not.
constexpr size_t kExtraAddressSpace = size_t(1) << 30;

Outcome loadInChild(const fs::path& path) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    std::fflush(nullptr);
    const size_t cap = virtualBytesNow() + kExtraAddressSpace;
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        rlimit limit{cap, cap};
        setrlimit(RLIMIT_AS, &limit);
        std::vector<std::string> warnings;
        GltfLoadOptions options;
        options.warnings = &warnings;
        Result<Scene> scene = loadGltf(path.string(), options);
        std::string report = scene.ok() ? "ok\n" : "error\n" + scene.error() + "\n";
        for (const std::string& w : warnings)
            report += w + "\n";
        for (size_t done = 0; done < report.size();) {
            ssize_t n = write(fds[1], report.data() + done, report.size() - done);
            if (n <= 0) break;
            done += size_t(n);
        }
        _exit(0);
    }
    close(fds[1]);
    std::string text;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;)
        text.append(buffer, size_t(n));
    close(fds[0]);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    Outcome o;
    o.peakRssKiB = usage.ru_maxrss;
    o.exited = WIFEXITED(status);
    o.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);
    o.ok = line == "ok";
    if (!o.ok) std::getline(lines, o.error);
    while (std::getline(lines, line))
        o.warnings.push_back(line);
    return o;
}

// Every file and folder under `dir`, to show the loader wrote nothing.
std::set<std::string> listing(const fs::path& dir) {
    std::set<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        out.insert(e.path().lexically_relative(dir).string() + " " +
                   std::to_string(e.is_regular_file() ? e.file_size() : 0));
    return out;
}

class HostileGltf : public ::testing::Test {
  protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("triptych_hostile_" + std::to_string(::getpid()));
        fs::remove_all(root_);
        cases_ = hostile::writeHostileScenes(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
    std::vector<hostile::Case> cases_;
};

// Peak resident memory of a child that loads one of these scenes: the test process it
// inherits (tens of MiB) plus at most one 64x64 texture and a triangle. 256 MiB is far below
// anything a believed count (2^24 vertices: 192 MiB of positions alone, then normals and
// tangents) or header (40 GB) would touch.
constexpr long kPeakRssLimitKiB = 256 * 1024;

TEST_F(HostileGltf, EveryCaseFailsCleanlyOrWarns) {
    ASSERT_GE(cases_.size(), 30u);
    std::set<std::string> names;
    for (const hostile::Case& c : cases_) {
        SCOPED_TRACE(c.name + ": " + c.what);
        EXPECT_TRUE(names.insert(c.name).second) << "duplicate case name";
        const fs::path dir = root_ / c.name;
        const fs::path scene = dir / c.scene;
        const std::set<std::string> before = listing(root_);
        Outcome o = loadInChild(scene);
        std::printf("[ hostile  ] %-36s %s\n", c.name.c_str(),
                    !o.exited ? ("died with signal " + std::to_string(o.signal)).c_str()
                    : o.ok    ? ("loaded; " +
                              (o.warnings.empty() ? std::string("no warning") : o.warnings.front()))
                                 .c_str()
                           : o.error.c_str());
        ASSERT_TRUE(o.exited) << "the load crashed or was killed (signal " << o.signal << ")";
        EXPECT_LT(o.peakRssKiB, kPeakRssLimitKiB);
        EXPECT_EQ(listing(root_), before) << "the loader wrote or removed files";
        if (c.expect == hostile::Expect::Error) {
            ASSERT_FALSE(o.ok) << "loaded, but must fail with '" << c.mention << "'";
            EXPECT_EQ(o.error.rfind(scene.string() + ": ", 0), 0u) << o.error;
            EXPECT_NE(o.error.find(c.mention), std::string::npos) << o.error;
            EXPECT_EQ(o.error.find("out of memory"), std::string::npos) << o.error;
        } else {
            ASSERT_TRUE(o.ok) << o.error;
            bool mentioned = false;
            for (const std::string& w : o.warnings)
                mentioned |= w.find(c.mention) != std::string::npos;
            EXPECT_TRUE(mentioned) << "no warning mentions '" << c.mention << "'";
        }
    }
}

// A warning case is still a usable scene: the texture is a 1x1 placeholder, the triangle is there.
TEST_F(HostileGltf, MissingTextureFallsBackToAPlaceholder) {
    std::vector<std::string> warnings;
    GltfLoadOptions options;
    options.warnings = &warnings;
    Result<Scene> scene = loadGltf((root_ / "texture_missing" / "scene.gltf").string(), options);
    ASSERT_TRUE(scene.ok()) << scene.error();
    EXPECT_EQ(scene->triangleCount(), 1u);
    ASSERT_EQ(scene->materials.size(), 1u);
    int32_t t = scene->materials[0].baseColorTexture;
    ASSERT_GE(t, 0);
    EXPECT_EQ(scene->textures[size_t(t)].width, 1u);
    EXPECT_EQ(scene->textures[size_t(t)].name, "placeholder:baseColor");
    ASSERT_EQ(warnings.size(), 1u);
}

// Every prefix of a valid file is a truncated file: one line, no crash, whatever the cut.
TEST(HostileGltfBytes, EveryTruncationFailsWithOneLine) {
    const fs::path folder = fs::temp_directory_path();
    for (bool binary : {false, true}) {
        const std::vector<uint8_t> whole =
            binary ? hostile::validTriangleGlb() : hostile::validTriangleGltf();
        Result<Scene> full = gltf::loadGltfBytes(whole, "whole", folder, binary);
        ASSERT_TRUE(full.ok()) << full.error();
        EXPECT_EQ(full->triangleCount(), 1u);
        size_t failed = 0;
        for (size_t n = 0; n < whole.size(); ++n) {
            std::vector<uint8_t> cut(whole.begin(), whole.begin() + long(n));
            Result<Scene> s = gltf::loadGltfBytes(cut, "cut.glb", folder, binary);
            if (s.ok()) continue;
            ++failed;
            EXPECT_EQ(s.error().rfind("cut.glb: ", 0), 0u) << s.error();
            EXPECT_EQ(s.error().find('\n'), std::string::npos) << s.error();
        }
        EXPECT_EQ(failed, whole.size()) << (binary ? "glb" : "gltf");
    }
}

// --- What the fuzzer found (tests/fuzz/regressions/gltf; docs/hostile_input.md, "Fuzzing") --

std::vector<uint8_t> readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

void writeBytes(const fs::path& path, const std::vector<uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

fs::path regression(const char* name) {
    return fs::path(TP_FUZZ_REGRESSIONS) / "gltf" / name;
}

// A regression input loaded as the child loads the hostile cases: image 0 must be refused
// before decoding, with one warning saying why (its meshes, mutated too, may fail the load
// afterwards; materials are read first).
void expectImageRefused(const fs::path& root, const char* input, const std::string& why) {
    fs::create_directories(root);
    const fs::path scene = root / (std::string(input));
    fs::copy_file(regression(input), scene, fs::copy_options::overwrite_existing);
    Outcome o = loadInChild(scene);
    ASSERT_TRUE(o.exited) << "signal " << o.signal;
    EXPECT_LT(o.peakRssKiB, kPeakRssLimitKiB);
    bool said = false;
    for (const std::string& w : o.warnings)
        said |= w == scene.string() + ": image 0: refused before decoding: " + why +
                         "; using a placeholder";
    EXPECT_TRUE(said) << "no warning says '" << why
                      << "'; the first: " << (o.warnings.empty() ? "(none)" : o.warnings.front());
}

// stb grew its buffer to an IDAT chunk's declared 1.7 GB before reading it (the fuzzer's
// malloc limit stopped a 2 GiB realloc; in a 32-bit address space it is an out-of-memory).
TEST_F(HostileGltf, FuzzFindingIdatLongerThanTheImage) {
    expectImageRefused(
        root_, "png_idat_length_past_end_2gib.glb",
        "its chunk 'IDAT' of 1696728432 bytes runs past the end of the image (9674 bytes)");
}

// An empty first IDAT made stb memcpy into its null buffer (UBSan; the fuzz replay in ctest
// catches that part); the damaged chunk after it is what refuses this one.
TEST_F(HostileGltf, FuzzFindingEmptyIdatThenDamagedChunk) {
    expectImageRefused(
        root_, "png_empty_idat_then_chunk_past_end.glb",
        "its chunk 0xf9c74736 of 164894549 bytes runs past the end of the image (9674 bytes)");
}

// The fuzzer flagged "a normal, tangent or uv that is not finite": its check summed the
// components, and uvs of 7.3e37 and 3.2e38 sum past fp32. Such (finite) uvs overflow the
// GPU's texture addressing: the loader clamps them to kMaxUvMagnitude (2^112) and says so.
TEST(HostileGltfBytes, FuzzFindingHugeFiniteUvs) {
    const std::vector<uint8_t> bytes = readBytes(regression("huge_finite_uvs_sum_overflows.glb"));
    ASSERT_EQ(bytes.size(), 26220u);
    GltfLoadOptions options; // as fuzz_gltf loaded it: by the length, neither option
    Result<Scene> scene =
        gltf::loadGltfBytes(bytes, "uvs.glb", fs::temp_directory_path(), false, options);
    ASSERT_TRUE(scene.ok()) << scene.error();
    float largest = 0.0f;
    for (const Mesh& m : scene->meshes)
        for (size_t i = 0; i < m.positions.size(); ++i) {
            for (int k = 0; k < 3; ++k)
                ASSERT_TRUE(std::isfinite(m.positions[i][k]) && std::isfinite(m.normals[i][k]));
            for (int k = 0; k < 4; ++k)
                ASSERT_TRUE(std::isfinite(m.tangents[i][k]) && std::isfinite(m.colors[i][k]));
            for (int k = 0; k < 2; ++k) {
                ASSERT_TRUE(std::isfinite(m.uvs[i][k]));
                largest = std::max(largest, std::abs(m.uvs[i][k]));
            }
        }
    EXPECT_EQ(largest, 0x1p112f);
    bool noted = false;
    for (const SceneRepair& r : scene->repairs)
        noted |= r.attribute == "TEXCOORD_0" && r.problem.find("(largest 3.") != std::string::npos;
    EXPECT_TRUE(noted);
}

using Bytes = std::vector<uint8_t>;

// An 8-bit RGBA PNG of `width` x `height` around a zlib stream (`stream`), as one IDAT, with
// an empty IDAT in front when `emptyFirst`.
Bytes pngAround(uint32_t width, uint32_t height, const Bytes& stream, bool emptyFirst) {
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
        be32(uint32_t(crc32(0, png.data() + start, uInt(png.size() - start))));
    };
    Bytes ihdr;
    for (uint32_t x : {width, height})
        for (int s = 24; s >= 0; s -= 8)
            ihdr.push_back(uint8_t(x >> s));
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});
    chunk("IHDR", ihdr);
    if (emptyFirst) chunk("IDAT", {});
    chunk("IDAT", stream);
    chunk("IEND", {});
    return png;
}

// `zeros` bytes of zeros (filter 0, black transparent pixels), deflated: ~1 KB per MiB.
Bytes deflatedZeros(size_t zeros) {
    z_stream z{};
    deflateInit(&z, Z_BEST_COMPRESSION);
    const Bytes block(1 << 20, 0);
    Bytes out, buffer(1 << 16);
    for (size_t left = zeros; left > 0 || z.avail_in > 0;) {
        const bool last = left <= block.size() && z.avail_in == 0;
        if (z.avail_in == 0) {
            z.next_in = const_cast<uint8_t*>(block.data());
            z.avail_in = uInt(std::min(left, block.size()));
            left -= z.avail_in;
        }
        int status;
        do {
            z.next_out = buffer.data();
            z.avail_out = uInt(buffer.size());
            status = deflate(&z, last && left == 0 ? Z_FINISH : Z_NO_FLUSH);
            out.insert(out.end(), buffer.data(), buffer.data() + (buffer.size() - z.avail_out));
        } while (z.avail_out == 0 || (last && left == 0 && status != Z_STREAM_END));
    }
    deflateEnd(&z);
    return out;
}

// The one-triangle scene with `png` as its base colour texture (img.png beside it).
fs::path texturedTriangle(const fs::path& dir, const Bytes& png) {
    fs::create_directories(dir);
    const Bytes text = hostile::validTriangleGltf();
    nlohmann::json g = nlohmann::json::parse(text.begin(), text.end());
    g["images"] = {{{"uri", "img.png"}}};
    g["textures"] = {{{"source", 0}}};
    g["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    g["meshes"][0]["primitives"][0]["material"] = 0;
    const std::string json = g.dump();
    writeBytes(dir / "scene.gltf", Bytes(json.begin(), json.end()));
    writeBytes(dir / "img.png", png);
    return dir / "scene.gltf";
}

// 16x16 pixels need 1,040 bytes of scanlines; a stream of 320 MiB of zeros is 320 KB of
// deflate. stb took it whole (it only checks there is enough) and held 320 MiB and more.
TEST_F(HostileGltf, ZlibBombRefusedBeforeDecoding) {
    const fs::path scene = texturedTriangle(
        root_ / "bomb", pngAround(16, 16, deflatedZeros(size_t(320) << 20), false));
    Outcome o = loadInChild(scene);
    ASSERT_TRUE(o.exited) << "signal " << o.signal;
    ASSERT_TRUE(o.ok) << o.error;
    EXPECT_LT(o.peakRssKiB, kPeakRssLimitKiB);
    ASSERT_EQ(o.warnings.size(), 1u);
    EXPECT_EQ(o.warnings[0], scene.string() +
                                 ": image 0 'img.png': refused before decoding: its image "
                                 "data inflates to more than 2080 bytes, twice what its size "
                                 "needs; using a placeholder");
}

// A valid PNG whose first IDAT is empty (the case behind the null memcpy): decoded from a
// copy without it, to the same pixels.
TEST_F(HostileGltf, EmptyFirstIdatDecodes) {
    const Bytes rows = {0, 255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 0, 255, 255, 255, 255, 255, 255};
    Bytes stream(compressBound(uLong(rows.size())));
    uLongf length = uLongf(stream.size());
    ASSERT_EQ(compress(stream.data(), &length, rows.data(), uLong(rows.size())), Z_OK);
    stream.resize(length);
    for (bool empty : {false, true}) {
        std::vector<std::string> warnings;
        GltfLoadOptions options;
        options.warnings = &warnings;
        const fs::path scene =
            texturedTriangle(root_ / (empty ? "empty" : "plain"), pngAround(2, 2, stream, empty));
        Result<Scene> s = loadGltf(scene.string(), options);
        ASSERT_TRUE(s.ok()) << s.error();
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        ASSERT_EQ(s->textures.size(), 1u);
        EXPECT_EQ(s->textures[0].rgba8,
                  (Bytes{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}));
    }
}

} // namespace
