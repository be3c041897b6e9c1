#include "core/cli/shadow_option.h"

#include <cstdlib>

#include "core/cli/options.h"

namespace tp {

ShadowSettings parseShadowCount(const std::string& text, ShadowSettings base) {
    base.all = false;
    base.count = 0;
    if (text == "none") return base;
    if (text == "all") {
        base.all = true;
        return base;
    }
    char* end = nullptr;
    const unsigned long n = std::strtoul(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || text[0] == '-' || n == 0 || n > 65536)
        throw cli::UsageError("--shadows: expected none, all or a light count in 1..65536, got '" +
                              text + "'");
    base.count = uint32_t(n);
    return base;
}

std::string shadowCountText(const ShadowSettings& s) {
    if (s.all) return "all";
    return s.count == 0 ? "none" : std::to_string(s.count);
}

} // namespace tp
