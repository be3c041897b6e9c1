#include "core/calibrate/calibration_file.h"

#include <filesystem>

#include "core/util/files.h"

namespace tp {
namespace {

using nlohmann::json;

json ceilingsToJson(const std::vector<Ceiling>& ceilings) {
    json out = json::array();
    for (const Ceiling& c : ceilings)
        out.push_back({{"name", c.name}, {"unit", c.unit}, {"what", c.what}, {"median", c.median},
                       {"min", c.min}, {"max", c.max}, {"median_ms", c.medianMs}, {"work", c.work},
                       {"repeats", c.repeats}});
    return out;
}

// The key's device and driver, which every reader shows or matches.
bool hasDeviceKey(const json& file) {
    const json key = file.value("key", json());
    return key.is_object() && key.value("device", json()).is_string() && key.value("driver", json()).is_string();
}

} // namespace

json calibrationJson(const json& key, const std::string& measuredAt, uint32_t repeats,
                     const std::vector<std::string>& command, const std::vector<Ceiling>& ceilings) {
    return {{"schema", kCalibrationSchema}, {"key", key}, {"measured_at", measuredAt},
            {"repeats", repeats}, {"command", command}, {"ceilings", ceilingsToJson(ceilings)}};
}

Status writeCalibration(const std::string& path, const json& file) {
    return writeTextFile(path, file.dump(2) + "\n");
}

std::optional<json> readCalibration(const std::string& path) {
    if (!std::filesystem::exists(path)) return std::nullopt;
    Result<std::string> text = readWholeFile(path);
    json file = text ? json::parse(*text, nullptr, false) : json();
    return file.is_discarded() ? json() : file;
}

bool isCalibration(const json& file) {
    return file.is_object() && file.value("schema", json()) == json(kCalibrationSchema); // any type: no throw
}

bool isCompleteCalibration(const json& file) {
    if (!file.value("measured_at", json()).is_string() || !file.value("ceilings", json()).is_array())
        return false;
    for (const json& c : file["ceilings"])
        for (const char* k : {"median", "min", "max"})
            if (!c.is_object() || !c.value(k, json()).is_number() || !c.value("unit", json()).is_string() ||
                !c.value("what", json()).is_string() || !c.value("name", json()).is_string())
                return false;
    return hasDeviceKey(file);
}

std::optional<json> reusableCalibration(const json& file, const json& key, std::string& why) {
    if (!isCalibration(file) || !isCompleteCalibration(file)) {
        why = "not a complete calibration";
        return std::nullopt;
    }
    if (file["key"] != key) {
        why = "made for another device, driver, build or mode";
        return std::nullopt;
    }
    std::vector<std::string> names;
    for (const json& c : file["ceilings"])
        names.push_back(c["name"]);
    if (names != ceilingNames()) {
        why = "its ceilings are not this build's";
        return std::nullopt;
    }
    return file;
}

std::optional<CeilingRates> ceilingRatesOf(const json& file) {
    CeilingRates rates;
    for (const json& c : file.value("ceilings", json::array())) {
        if (!c.is_object() || !c.value("name", json()).is_string() || !c.value("median", json()).is_number())
            return std::nullopt;
        rates[c["name"].get<std::string>()] = c["median"].get<double>() * 1e9;
    }
    return rates;
}

// Lighter than isCompleteCalibration: the viewer needs only the medians, and whose they are.
Result<CeilingFile> readCeilingFile(const std::string& path) {
    const Error bad{path + " is not a complete triptych calibration"};
    Result<std::string> text = readWholeFile(path);
    if (!text) return Error{text.error()};
    const json f = json::parse(*text, nullptr, false);
    if (!isCalibration(f) || !f.value("ceilings", json()).is_array() || !hasDeviceKey(f) ||
        !f.value("measured_at", json()).is_string())
        return bad;
    std::optional<CeilingRates> rates = ceilingRatesOf(f);
    if (!rates) return bad;
    CeilingFile out{path, f["key"]["device"], f["key"]["driver"], f["measured_at"], std::move(*rates)};
    return out;
}

} // namespace tp
