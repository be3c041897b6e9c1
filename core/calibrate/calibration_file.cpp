#include "core/calibrate/calibration_file.h"

#include <nlohmann/json.hpp>

#include "core/util/files.h"

namespace tp {

std::optional<CeilingRates> ceilingRatesOf(const nlohmann::json& file) {
    CeilingRates rates;
    for (const nlohmann::json& c : file.value("ceilings", nlohmann::json::array())) {
        if (!c.is_object() || !c.value("name", nlohmann::json()).is_string() || !c.value("median", nlohmann::json()).is_number())
            return std::nullopt;
        rates[c["name"].get<std::string>()] = c["median"].get<double>() * 1e9;
    }
    return rates;
}

Result<CeilingFile> readCeilingFile(const std::string& path) {
    const Error bad{path + " is not a complete triptych calibration"};
    Result<std::string> text = readWholeFile(path);
    if (!text) return Error{text.error()};
    const nlohmann::json f = nlohmann::json::parse(*text, nullptr, false);
    if (!f.is_object() || f.value("schema", nlohmann::json()) != nlohmann::json("triptych.calibration/1") || !f.value("ceilings", nlohmann::json()).is_array() ||
        !f.value("key", nlohmann::json()).is_object() || !f["key"].value("device", nlohmann::json()).is_string() ||
        !f["key"].value("driver", nlohmann::json()).is_string() || !f.value("measured_at", nlohmann::json()).is_string())
        return bad;
    std::optional<CeilingRates> rates = ceilingRatesOf(f);
    if (!rates) return bad;
    CeilingFile out{path, f["key"]["device"], f["key"]["driver"], f["measured_at"], std::move(*rates)};
    return out;
}

} // namespace tp
