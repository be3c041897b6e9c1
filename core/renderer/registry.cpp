// The name -> factory registry. Pipelines add themselves from their own folders with a
// static RendererRegistration (the build links every object file, see CMakeLists.txt), so
// nothing here or in the CLI lists them.
#include <algorithm>
#include <stdexcept>

#include "core/gpu/context.h"
#include "core/renderer/renderer.h"

namespace tp {
namespace {

std::vector<RendererEntry>& registry() {
    static std::vector<RendererEntry> entries;
    return entries;
}

void checkSharedKnobs(const RendererEntry& entry) {
    for (const RendererEntry& other : registry())
        for (const Knob& a : other.name == entry.name ? KnobSchema{} : other.knobs)
            for (const Knob& b : entry.knobs)
                if (a.name == b.name && !(a == b))
                    throw std::logic_error("knob '--" + a.name + "' is declared differently by " +
                                           other.name + " and " + entry.name +
                                           ": a shared knob must be one declaration");
}

} // namespace

void registerRenderer(RendererEntry entry) {
    auto& r = registry();
    checkSharedKnobs(
        entry); // before anything changes: a refused entry leaves the registry as it was
    std::erase_if(r, [&](const RendererEntry& e) { return e.name == entry.name; });
    auto at = std::find_if(r.begin(), r.end(), [&](const RendererEntry& e) {
        return e.order > entry.order || (e.order == entry.order && e.name > entry.name);
    });
    r.insert(at, std::move(entry));
}

const std::vector<RendererEntry>& registeredRenderers() {
    return registry();
}

Result<const RendererEntry*> findRenderer(const std::string& name) {
    for (const RendererEntry& e : registeredRenderers())
        if (e.name == name) return &e;
    std::string names;
    for (const RendererEntry& e : registeredRenderers())
        names += (names.empty() ? "" : ", ") + e.name;
    return Error{"unknown pipeline '" + name + "' (available: " + names + ")"};
}

std::vector<KnobReaders> allKnobs() {
    std::vector<KnobReaders> all;
    for (const RendererEntry& e : registeredRenderers())
        for (const Knob& k : e.knobs) {
            auto it = std::find_if(all.begin(), all.end(),
                                   [&](const KnobReaders& r) { return r.knob.name == k.name; });
            if (it == all.end())
                all.push_back({k, {e.name}});
            else
                it->readers.push_back(e.name);
        }
    return all;
}

Status checkSampleCount(const GpuContext& ctx, uint32_t samples) {
    // A power of two the device reports for colour and depth (DeviceCaps::colorSampleCounts).
    const bool power = samples != 0 && (samples & (samples - 1)) == 0 && samples <= 64;
    if (!power || !(ctx.caps.colorSampleCounts & samples))
        return Error{"--msaa " + std::to_string(samples) + ": not supported by " + ctx.info.name};
    return {};
}

std::unique_ptr<Renderer> createRenderer(const RendererEntry& entry, RendererCreateInfo info) {
    if (Status s = checkSampleCount(info.ctx, info.settings.msaa); !s)
        throw RendererError(s.error());
    if (Status s = resolveKnobs(entry.knobs, info.settings); !s) throw RendererError(s.error());
    return entry.factory(info);
}

} // namespace tp
