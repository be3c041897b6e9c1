// libFuzzer target: the lights JSON parser. Accepted lights must be within the documented
// bounds (core/scene/lights.h) and survive a write and a read unchanged; an error must be one
// line naming the file. Anything else aborts, which libFuzzer reports as a finding.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/scene/lights.h"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
    std::fprintf(stderr, "fuzz_lights: %s: %s\n", what, detail.c_str());
    std::abort();
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    tp::Result<std::vector<tp::Light>> lights = tp::lightsFromJson(text, "fuzz.json");
    if (!lights) {
        if (lights.error().find('\n') != std::string::npos ||
            lights.error().rfind("fuzz.json: ", 0) != 0)
            broken("error", lights.error());
        return 0;
    }
    for (const tp::Light& l : *lights) {
        if (!finite(l.position) || !finite(l.direction) || !finite(l.color) ||
            !std::isfinite(l.intensity) || !std::isfinite(l.range))
            broken("accepted", "a value that is not finite");
        if (l.intensity < 0 || l.range < 0 || l.color.r < 0 || l.color.g < 0 || l.color.b < 0)
            broken("accepted", "a negative value");
        if (l.type != tp::LightType::Directional &&
            (!(l.range > 0) || l.range > tp::kMaxLightRange))
            broken("accepted", "a range outside (0, 1e10]");
        if (l.innerConeAngle > l.outerConeAngle) broken("accepted", "inner cone past outer");
    }
    tp::Result<std::vector<tp::Light>> again =
        tp::lightsFromJson(tp::lightsToJson(*lights), "again.json");
    if (!again) broken("round trip", again.error());
    if (again->size() != lights->size()) broken("round trip", "a different number of lights");
    for (size_t i = 0; i < lights->size(); ++i)
        if (std::memcmp(&(*again)[i], &(*lights)[i], sizeof(tp::Light)) != 0)
            broken("round trip", "light " + std::to_string(i) + " changed");
    return 0;
}
