// The glTF loader against hostile scenes (tests/cli/hostile_scenes.h): each is loaded in a
// child process with its address space capped, so a loader that believed a header or a count
// would fail there (or be killed) instead of taking the machine's memory; the child's peak
// resident memory is checked too. The CLI runs the same cases end to end
// (tests/cli/hostile_input.sh).
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <sstream>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

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
                    : o.ok    ? ("loaded; " + (o.warnings.empty() ? std::string("no warning")
                                                                  : o.warnings.front()))
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

} // namespace
