#include "core/renderer/knobs.h"

#include <algorithm>

#include "core/renderer/renderer.h"

namespace tp {
namespace {

bool wholeNumber(const std::string& text, uint32_t& out) {
    if (text.empty() || text.size() > 10 ||
        text.find_first_not_of("0123456789") != std::string::npos)
        return false;
    const unsigned long long v = std::stoull(text);
    if (v > 0xffffffffull) return false;
    out = uint32_t(v);
    return true;
}

} // namespace

Knob Knob::choice(std::string name, std::vector<std::string> values, std::string help) {
    Knob k;
    k.name = std::move(name);
    k.values = std::move(values);
    k.defaultValue = k.values.empty() ? std::string() : k.values.front();
    k.help = std::move(help);
    return k;
}

Knob Knob::integer(std::string name, uint32_t min, uint32_t max, uint32_t defaultValue,
                   std::string help) {
    Knob k = choice(std::move(name), {}, std::move(help));
    k.kind = Kind::Integer;
    k.min = min;
    k.max = max;
    k.defaultValue = std::to_string(defaultValue);
    return k;
}

Knob Knob::integerOf(std::string name, std::vector<std::string> values, std::string defaultValue,
                     std::string help) {
    Knob k = choice(std::move(name), std::move(values), std::move(help));
    k.kind = Kind::Integer;
    k.defaultValue = std::move(defaultValue);
    return k;
}

const std::string& Knob::valueIn(const std::map<std::string, std::string>& values) const {
    auto it = values.find(name);
    return it == values.end() ? defaultValue : it->second;
}

std::string Knob::key() const {
    std::string k = name;
    std::replace(k.begin(), k.end(), '-', '_');
    return k;
}

std::string Knob::allowedText() const {
    if (kind == Kind::Integer && values.empty())
        return std::to_string(min) + " to " + std::to_string(max);
    std::string text;
    for (const std::string& v : values)
        text += (text.empty() ? "" : ", ") + v;
    return text;
}

Status Knob::check(const std::string& value) const {
    uint32_t n = 0;
    const bool listed = std::find(values.begin(), values.end(), value) != values.end();
    const bool ok = kind == Kind::Choice
                        ? listed
                        : wholeNumber(value, n) && (values.empty() ? n >= min && n <= max : listed);
    if (ok) return {};
    return Error{"--" + name + " '" + value + "': allowed values are " + allowedText()};
}

void throwNotAValue(const Knob& knob, const std::string& value) {
    throw RendererError("knob '" + knob.name + "': '" + value + "' is none of " +
                        knob.allowedText());
}

Status resolveKnobs(const KnobSchema& schema, RenderSettings& s) {
    for (const Knob& k : schema) {
        auto it = s.knobs.find(k.name);
        if (it == s.knobs.end()) {
            s.knobs[k.name] = k.defaultValue;
            continue;
        }
        if (Status st = k.check(it->second); !st) return st;
    }
    return {};
}

const std::string& RenderSettings::text(const std::string& name) const {
    auto it = knobs.find(name);
    if (it == knobs.end())
        throw RendererError("knob '" + name + "' has no value (not declared by this renderer?)");
    return it->second;
}

uint32_t RenderSettings::integer(const std::string& name) const {
    uint32_t n = 0;
    if (!wholeNumber(text(name), n))
        throw RendererError("knob '" + name + "': '" + text(name) + "' is not a whole number");
    return n;
}

RenderSettings& RenderSettings::set(const std::string& name, const std::string& value) {
    knobs[name] = value;
    return *this;
}

RenderSettings& RenderSettings::set(const std::string& name, uint32_t value) {
    return set(name, std::to_string(value));
}

} // namespace tp
