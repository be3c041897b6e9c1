#include <algorithm>

#include "core/render/renderer.h"

namespace tp {

void registerBuiltinRenderers(); // compare/pipelines.cpp: the list of pipelines this build has

namespace {
std::vector<RendererEntry>& registry() {
    static std::vector<RendererEntry> entries;
    return entries;
}
} // namespace

void registerRenderer(RendererEntry entry) {
    auto& r = registry();
    std::erase_if(r, [&](const RendererEntry& e) { return e.name == entry.name; });
    r.push_back(std::move(entry));
}

const std::vector<RendererEntry>& registeredRenderers() {
    static bool once = (registerBuiltinRenderers(), true);
    (void)once;
    return registry();
}

Result<const RendererEntry*> findRenderer(const std::string& name) {
    for (const RendererEntry& e : registeredRenderers())
        if (e.name == name) return &e;
    std::string names;
    for (const RendererEntry& e : registeredRenderers()) names += (names.empty() ? "" : ", ") + e.name;
    return Error{"unknown pipeline '" + name + "' (available: " + names + ")"};
}

} // namespace tp
