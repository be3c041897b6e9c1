// Lets a header be compiled as GLSL and as C++ (glm mimics GLSL), so the light model,
// BRDF and tonemap exist once and the CPU tests exercise the very code the GPU runs.
// Rules for shared code: float literals with an f suffix, no in/out/inout parameters,
// no GLSL-only built-ins.
#ifndef TP_GLSL_CPP_H
#define TP_GLSL_CPP_H
// A struct that crosses to the GPU: declared with TP_STRUCT so the header reads alike in both
// languages (C++ mirrors it with static_asserts on size and offsets).
#define TP_STRUCT(name) struct name
#ifdef TP_GLSL
#define TP_INLINE
#else
#include <cstdint>
#include <glm/glm.hpp>
#define TP_INLINE inline
namespace tp::gpu {
using glm::clamp;
using glm::dot;
using glm::dvec3;
using glm::dvec4;
using glm::ivec2;
using glm::ivec4;
using glm::max;
using glm::min;
using glm::mat4;
using glm::mix;
using glm::normalize;
using glm::uvec2;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
using glm::length;
using glm::pow;
using glm::sqrt;
using glm::exp2;
using uint = uint32_t;
} // namespace tp::gpu
#endif
#endif
