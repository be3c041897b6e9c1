#include "core/renderer/view_settings.h"

#include "core/renderer/renderer.h"

namespace tp {
namespace {

// "1, 2, 4 or 8"
std::string msaaCountsText() {
    std::string text;
    for (size_t i = 0; i < kMsaaCounts.size(); ++i)
        text += (i == 0                        ? ""
                 : i + 1 == kMsaaCounts.size() ? " or "
                                               : ", ") +
                std::to_string(kMsaaCounts[i]);
    return text;
}

} // namespace

Status checkSetting(const std::string& name, const std::string& value) {
    if (name == kMsaaSetting) {
        for (uint32_t n : kMsaaCounts)
            if (value == std::to_string(n)) return {};
        return Error{"--msaa " + value + ": must be " + msaaCountsText()};
    }
    for (const KnobReaders& k : allKnobs())
        if (k.knob.name == name) return k.knob.check(value);
    return Error{"no pipeline has a knob '" + name + "'"};
}

bool parseResolution(const std::string& text, uint32_t& width, uint32_t& height) {
    const size_t x = text.find_first_of("xX");
    auto side = [](const std::string& digits, uint32_t& out) {
        if (digits.empty() || digits.size() > 9) return false;
        for (char c : digits)
            if (c < '0' || c > '9') return false;
        out = uint32_t(std::stoul(digits));
        return true;
    };
    return x != std::string::npos && side(text.substr(0, x), width) &&
           side(text.substr(x + 1), height);
}

} // namespace tp
