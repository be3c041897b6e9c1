#include "core/gpu/shader_reflection.h"

#include <algorithm>
#include <map>
#include <mutex>

#include <spirv_cross_c.h>

#include "core/gpu/embedded_shaders.h"
#include "include/shared.h"

namespace tp {
namespace {

struct Reflected {
    spvc_resource_type spvc;
    VkDescriptorType vk;
};

constexpr Reflected kTypes[] = {
    {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
    {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE},
    {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, VK_DESCRIPTOR_TYPE_SAMPLER},
    {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
    {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
};

// Owns a SPIRV-Cross context for the duration of one reflection.
struct Context {
    spvc_context ctx = nullptr;
    Context() { spvc_context_create(&ctx); }
    ~Context() { spvc_context_destroy(ctx); }
};

std::string bindingText(const SetBinding& b) {
    return "binding " + std::to_string(b.binding) + " (" + descriptorTypeName(b.type) + ")";
}

const SetBinding* find(const std::vector<SetBinding>& list, uint32_t binding) {
    for (const SetBinding& b : list)
        if (b.binding == binding) return &b;
    return nullptr;
}

} // namespace

const char* descriptorTypeName(VkDescriptorType type) {
    switch (type) {
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
        return "combined image sampler";
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
        return "sampled image";
    case VK_DESCRIPTOR_TYPE_SAMPLER:
        return "sampler";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
        return "storage image";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
        return "storage buffer";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
        return "uniform buffer";
    default:
        return "other descriptor";
    }
}

std::vector<SetBinding> reflectSetBindings(const uint32_t* words, size_t wordCount, uint32_t set) {
    Context c;
    spvc_parsed_ir ir = nullptr;
    spvc_compiler compiler = nullptr;
    spvc_resources resources = nullptr;
    if (spvc_context_parse_spirv(c.ctx, words, wordCount, &ir) != SPVC_SUCCESS ||
        spvc_context_create_compiler(c.ctx, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                     &compiler) != SPVC_SUCCESS ||
        spvc_compiler_create_shader_resources(compiler, &resources) != SPVC_SUCCESS)
        throw GraphError(std::string("SPIR-V reflection failed: ") +
                         spvc_context_get_last_error_string(c.ctx));
    std::vector<SetBinding> out;
    for (const Reflected& t : kTypes) {
        const spvc_reflected_resource* list = nullptr;
        size_t count = 0;
        spvc_resources_get_resource_list_for_type(resources, t.spvc, &list, &count);
        for (size_t i = 0; i < count; ++i) {
            if (spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet) !=
                set)
                continue;
            out.push_back(
                {spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding), t.vk});
        }
    }
    std::sort(out.begin(), out.end(),
              [](const SetBinding& a, const SetBinding& b) { return a.binding < b.binding; });
    return out;
}

const std::vector<SetBinding>& reflectShaderSet(const std::string& shader, uint32_t set) {
    static std::mutex mutex;
    static std::map<std::pair<std::string, uint32_t>, std::vector<SetBinding>> cache;
    std::lock_guard lock(mutex);
    auto key = std::make_pair(shader, set);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
    for (const EmbeddedShader& s : embeddedShaders())
        if (shader == s.name) return cache[key] = reflectSetBindings(s.words, s.wordCount, set);
    throw GraphError("no embedded shader named " + shader);
}

void checkPassBindings(const PassSet* declared, const std::vector<std::string>& shaders) {
    static const std::vector<SetBinding> none;
    const std::vector<SetBinding>& bound = declared ? declared->bindings : none;
    const std::string pass =
        declared ? "pass '" + declared->pass + "'" : "a pipeline without a pass set";
    for (const std::string& shader : shaders) {
        for (const SetBinding& b : reflectShaderSet(shader, TP_SET_PASS)) {
            const SetBinding* d = find(bound, b.binding);
            if (!d)
                throw BindingMismatch(pass + ": shader '" + shader + "' declares " +
                                      bindingText(b) + ", which the pass does not bind");
            if (d->type != b.type)
                throw BindingMismatch(pass + ": " + bindingText(*d) + " is declared as " +
                                      descriptorTypeName(b.type) + " by shader '" + shader + "'");
        }
    }
    for (const SetBinding& d : bound) {
        bool found = false;
        for (const std::string& shader : shaders)
            found = found || find(reflectShaderSet(shader, TP_SET_PASS), d.binding);
        if (!found) {
            std::string names;
            for (const std::string& s : shaders)
                names += (names.empty() ? "'" : ", '") + s + "'";
            throw BindingMismatch(pass + ": " + bindingText(d) + " is not declared by shader " +
                                  names);
        }
    }
}

} // namespace tp
