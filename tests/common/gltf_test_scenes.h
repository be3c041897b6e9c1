#pragma once
// glTF scenes the tests write themselves (docs/hostile_input.md): the same small mesh (a uv
// sphere on a floor, with a base colour texture) stored plainly, with NaN/infinite/zero-length
// attributes to repair, Draco-compressed (libdraco's encoder), meshopt-compressed
// (meshoptimizer's encoders, octahedral normals, a fallback buffer without a uri) and with
// KHR_texture_transform. Each writer returns the .gltf path inside `dir` (created).
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

namespace tp::test {

struct TestMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
};

// A sphere of radius 1 centred at (0, 1, 0) on a 6 x 6 floor at y = 0.
TestMesh makeTestMesh();

// How many values the repair scene spoils, per attribute.
struct RepairCounts {
    size_t nanNormals = 0, zeroNormals = 0, badTangents = 0, badUvs = 0;
};

std::filesystem::path writePlainScene(const std::filesystem::path& dir);
std::filesystem::path writeRepairScene(const std::filesystem::path& dir, RepairCounts& counts);
std::filesystem::path writeDracoScene(const std::filesystem::path& dir);
std::filesystem::path writeMeshoptScene(const std::filesystem::path& dir);
// offset (0.5, 0), rotation pi/2, scale (2, 1) on the base colour texture.
std::filesystem::path writeTextureTransformScene(const std::filesystem::path& dir);
// The plain mesh with an alpha-masked material (cutoff 0.5, double-sided) whose base colour
// texture cuts round holes: alpha-test boundaries everywhere, as on leaf cards and grilles.
std::filesystem::path writeMaskedScene(const std::filesystem::path& dir);

} // namespace tp::test
