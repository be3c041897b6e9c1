// The runs a sweep makes: its lists read and checked, each pipeline's knob combinations.
#include "compare/commands/sweep_plan.h"

#include <algorithm>
#include <sstream>

#include "core/renderer/renderer.h"
#include "core/renderer/view_settings.h"

namespace tp::cli {
namespace {

// A knob's values in this sweep: the given list (or single value), else its default.
std::vector<std::string> knobValues(const SweepOptions& o, const Knob& k) {
    if (!k.sweepable) return {k.valueIn(o.knobs)};
    return splitList(k.valueIn(o.knobs), ("--" + k.name).c_str());
}

} // namespace

std::vector<std::string> splitList(const std::string& text, const char* option) {
    std::vector<std::string> items;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) items.push_back(item);
    if (items.empty()) throw UsageError(std::string(option) + " '" + text + "': empty list");
    return items;
}

int toInt(const std::string& s, const char* option) {
    char* end = nullptr;
    long v = std::strtol(s.c_str(), &end, 10);
    if (end == s.c_str() || *end || v < 0 || v > 1000000)
        throw UsageError(std::string(option) + ": bad value '" + s + "'");
    return int(v);
}

void checkKnobLists(const SweepOptions& o) {
    for (const KnobReaders& k : allKnobs()) {
        if (!k.knob.sweepable) continue;
        for (const std::string& v : knobValues(o, k.knob))
            if (Status s = checkSetting(k.knob.name, v); !s) throw UsageError(s.error());
    }
}

std::vector<RenderSettings> knobCombos(const std::string& pipeline, const SweepOptions& o,
                                       const RenderSettings& base) {
    std::vector<RenderSettings> combos = {base};
    for (const KnobReaders& k : allKnobs()) {
        std::vector<std::string> values = knobValues(o, k.knob);
        if (std::find(k.readers.begin(), k.readers.end(), pipeline) == k.readers.end() ||
            (k.knob.msaaOnly && base.msaa == 1))
            values.resize(1);
        std::vector<RenderSettings> next;
        for (const RenderSettings& c : combos)
            for (const std::string& v : values) {
                next.push_back(c);
                next.back().set(k.knob.name, v);
            }
        combos = std::move(next);
    }
    return combos;
}

} // namespace tp::cli
