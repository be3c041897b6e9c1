#pragma once
// Hostile glTF scenes, written into a folder: one sub-folder per case, each with what the
// loader must say about it. Shared by the loader's tests (tests/cpu/hostile_gltf_test.cpp),
// the CLI test (tests/cli/hostile_input.sh, through make_hostile_scenes) and the fuzz seed
// corpus (tests/fuzz/run.sh). docs/hostile_input.md lists the cases.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tp::hostile {

enum class Expect {
    Error,   // the load fails with one line naming the file and containing `mention`
    Warning, // the scene loads (and renders) and one warning contains `mention`
};

struct Case {
    std::string name;  // its folder under the root
    std::string scene; // the scene's path inside that folder
    Expect expect;
    std::string mention;
    std::string what; // what is hostile about it, one line
};

// Writes every case under `root` (created; existing case folders are replaced).
std::vector<Case> writeHostileScenes(const std::filesystem::path& root);

// A valid one-triangle scene, for seeds: .gltf text with its buffer as a data URI, and .glb.
std::vector<uint8_t> validTriangleGltf();
std::vector<uint8_t> validTriangleGlb();

// The valid triangle's parts, for a test to break one way: its glTF, whose one buffer is the
// file "tri.bin", and that buffer's 44 bytes (three float positions, three uint16 indices).
nlohmann::json triangleJson();
std::vector<uint8_t> triangleBin();

} // namespace tp::hostile
