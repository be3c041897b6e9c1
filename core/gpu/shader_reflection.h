#pragma once
// SPIR-V reflection (SPIRV-Cross's C API) of the embedded shaders, and the check that a
// pipeline's shaders and its pass's descriptor set agree. It parses SPIR-V only, so it runs
// without a device (tests/cpu/frame_graph_test.cpp).
//
// The rule, checked at pipeline creation (core/gpu/pipelines.cpp):
//   - every set-TP_SET_PASS binding a shader of the pipeline declares is declared by the pass
//     with the same descriptor type (else the pipeline layout would not match the shader);
//   - every binding the pass declares is declared by at least one shader of the pipeline
//     (else a missed edit keeps a resource bound, alive and allocated for nothing).
// "Declares" means present in the SPIR-V, used or not: glslang keeps unused declarations,
// so a shader variant that compiles a binding out (#ifdef) must have a pass that does not
// bind it. A pass set shared by several pipelines is checked against each of them.
#include <string>
#include <vector>

#include "core/gpu/descriptors.h"
#include "core/gpu/graph_plan.h"

namespace tp {

// A pipeline's shaders disagree with its pass's declared bindings.
struct BindingMismatch : GraphError {
    using GraphError::GraphError;
};

const char* descriptorTypeName(VkDescriptorType type);

// The bindings of descriptor set `set` in SPIR-V `words`, sorted by binding.
std::vector<SetBinding> reflectSetBindings(const uint32_t* words, size_t wordCount, uint32_t set);
// The same for an embedded shader, reflected once and cached.
const std::vector<SetBinding>& reflectShaderSet(const std::string& shader, uint32_t set);

// Throws BindingMismatch naming the pass, the binding and the shader. `declared` is null for
// a pipeline without a pass set: then no shader may declare a set-TP_SET_PASS binding.
void checkPassBindings(const PassSet* declared, const std::vector<std::string>& shaders);

} // namespace tp
