#pragma once
// SPIR-V compiled at build time and embedded in the binary (cmake/EmbedShaders.cmake).
#include <cstdint>
#include <vector>

namespace tp {

struct EmbeddedShader {
    const char* name; // file name without extension, e.g. "reference.frag" -> "reference_frag"
    const uint32_t* words;
    uint32_t wordCount;
};

const std::vector<EmbeddedShader>& embeddedShaders();

} // namespace tp
