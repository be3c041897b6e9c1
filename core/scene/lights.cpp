#include "core/scene/lights.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/util/math.h"

namespace tp {

namespace {

constexpr size_t kMaxLights = 1000000;
// A lights file is at most this long: a million lights written by lightsToJson are ~150 MB.
constexpr uintmax_t kMaxLightsFileBytes = uintmax_t(512) << 20;
// Directions shorter than this have no reliable direction once normalized (the other bounds
// are in lights.h).
constexpr double kMinDirectionLength = 1e-6;

// splitmix64: tiny, fast, and the same numbers on every platform and standard library
// (std::uniform_*_distribution is not).
class Rng {
  public:
    explicit Rng(uint64_t seed) : state_(seed) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    float uniform() { return float(next() >> 40) * (1.0f / 16777216.0f); } // [0, 1)
    float uniform(float a, float b) { return a + (b - a) * uniform(); }

  private:
    uint64_t state_;
};

glm::vec3 hsvToRgb(float h, float s, float v) {
    glm::vec3 k = glm::mod(glm::vec3(5.0f, 3.0f, 1.0f) + h * 6.0f, 6.0f);
    glm::vec3 w = glm::clamp(glm::min(k, 4.0f - k), 0.0f, 1.0f);
    return v * (1.0f - s * w);
}

LightType pickType(float u, const LightGenOptions& o) {
    float wp = std::max(0.0f, o.pointWeight), ws = std::max(0.0f, o.spotWeight);
    float wd = std::max(0.0f, o.directionalWeight);
    float total = wp + ws + wd;
    if (!(total > 0.0f)) return LightType::Point;
    float x = u * total;
    if (x < wp) return LightType::Point;
    if (x < wp + ws || wd <= 0.0f) return LightType::Spot;
    return LightType::Directional;
}

// A direction within `maxTilt` of straight down.
glm::vec3 downward(float tiltU, float azimuthU, float maxTilt) {
    float tilt = tiltU * maxTilt, az = azimuthU * 2.0f * kPi;
    return glm::vec3(std::sin(tilt) * std::cos(az), -std::cos(tilt), std::sin(tilt) * std::sin(az));
}

} // namespace

std::vector<Light> generateLights(const Aabb& bounds, const LightGenOptions& o) {
    std::vector<Light> lights;
    if (o.count == 0) return lights;
    Aabb box = bounds.empty() ? Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)} : bounds;
    const glm::vec3 margin = box.extent() * 0.02f;
    const glm::vec3 lo = box.min + margin, hi = box.max - margin;
    const float diagonal = glm::length(box.extent());
    const float rMin = o.radiusMin > 0.0f ? o.radiusMin : 0.04f * diagonal;
    const float rMax = std::max(rMin, o.radiusMax > 0.0f ? o.radiusMax : 0.12f * diagonal);
    const bool autoIntensity = !(o.intensityMin > 0.0f && o.intensityMax > 0.0f);
    Rng rng(o.seed);
    lights.reserve(o.count);
    for (uint32_t i = 0; i < o.count; ++i) {
        // Always twelve draws per light, whatever its type, so one light's type does not shift
        // the numbers of the next.
        float u[12];
        for (float& x : u)
            x = rng.uniform();
        Light l;
        l.type = pickType(u[0], o);
        l.position = glm::mix(lo, hi, glm::vec3(u[1], u[2], u[3]));
        l.range = rMin + (rMax - rMin) * u[4];
        // Default: radius^2 x [0.3, 1.5] cd gives 1-5 lux at half the range.
        l.intensity = autoIntensity ? l.range * l.range * (0.3f + 1.2f * u[5])
                                    : o.intensityMin + (o.intensityMax - o.intensityMin) * u[5];
        l.color = hsvToRgb(u[6], 0.3f + 0.4f * u[7], 1.0f);
        if (l.type == LightType::Spot) {
            l.direction = downward(u[8], u[9], 0.6f);
            l.outerConeAngle = glm::radians(20.0f + 25.0f * u[10]);
            l.innerConeAngle = l.outerConeAngle * (0.6f + 0.3f * u[11]);
        } else if (l.type == LightType::Directional) {
            l.direction = downward(u[8], u[9], 0.8f);
            if (autoIntensity) l.intensity = 0.5f + 1.5f * u[5];
        }
        lights.push_back(l);
    }
    return lights;
}

// ---- JSON -----------------------------------------------------------------------------

namespace {

using nlohmann::json;

const char* typeName(LightType t) {
    switch (t) {
    case LightType::Point:
        return "point";
    case LightType::Spot:
        return "spot";
    case LightType::Directional:
        return "directional";
    }
    return "point";
}

// The double nearest the float's shortest decimal form, which JSON then prints as that form
// ("0.3", not the float's exact value "0.30000001192092896") and which reads back as the same
// float: a million lights' file a quarter smaller, the same lights.
// Decimal -> double -> float rounds twice, which for a few floats (e.g. 7.038531e-26, bits
// 0x15ae43fd: the double lands on a midpoint) is not the float: those keep their exact value.
double shortest(float f) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), f);
    double d = 0.0;
    if (ec != std::errc() || std::from_chars(buf, end, d).ec != std::errc() || float(d) != f)
        return double(f);
    return d;
}

json vecJson(const glm::vec3& v) {
    return json::array({shortest(v.x), shortest(v.y), shortest(v.z)});
}

json lightJson(const Light& l) {
    return json{{"type", typeName(l.type)},
                {"position", vecJson(l.position)},
                {"direction", vecJson(l.direction)},
                {"color", vecJson(l.color)},
                {"intensity", shortest(l.intensity)},
                {"range", shortest(l.range)},
                {"inner_cone", shortest(l.innerConeAngle)},
                {"outer_cone", shortest(l.outerConeAngle)}};
}

// Reads one light; returns an empty string or what is wrong, with `where` filled in.
struct LightReader {
    const json& obj;
    std::string where; // "lights[3]"
    std::string error;

    bool fail(const std::string& what, const char* field) {
        if (error.empty())
            error = what + " (at " + where + (field ? std::string(".") + field : "") + ")";
        return false;
    }
    bool number(const char* field, float& out, bool required, bool nonNegative) {
        auto it = obj.find(field);
        if (it == obj.end()) return required ? fail("missing field", field) : true;
        if (!it->is_number())
            return fail("expected a number, got " + std::string(it->type_name()), field);
        double d = it->get<double>();
        float f = float(d);
        if (!std::isfinite(d) || !std::isfinite(f))
            return fail("number is not finite as a float", field);
        if (nonNegative && f < 0.0f) return fail("must not be negative", field);
        out = f;
        return true;
    }
    bool atMost(const char* field, double value, double limit, const char* message) {
        return value <= limit || fail(message, field);
    }
    bool vec3(const char* field, glm::vec3& out, bool required) {
        auto it = obj.find(field);
        if (it == obj.end()) return required ? fail("missing field", field) : true;
        if (!it->is_array() || it->size() != 3)
            return fail("expected an array of 3 numbers", field);
        for (int k = 0; k < 3; ++k) {
            const json& e = (*it)[size_t(k)];
            if (!e.is_number()) return fail("expected an array of 3 numbers", field);
            double d = e.get<double>();
            if (!std::isfinite(d) || !std::isfinite(float(d)))
                return fail("number is not finite as a float", field);
            out[k] = float(d);
        }
        return true;
    }
};

bool readType(LightReader& r, LightType& type) {
    auto it = r.obj.find("type");
    if (it == r.obj.end()) return r.fail("missing field", "type");
    if (!it->is_string()) return r.fail("expected a string", "type");
    const std::string s = it->get<std::string>();
    if (s == "point")
        type = LightType::Point;
    else if (s == "spot")
        type = LightType::Spot;
    else if (s == "directional")
        type = LightType::Directional;
    else
        return r.fail("unknown light type '" + s + "' (valid: point, spot, directional)", "type");
    return true;
}

bool readLight(LightReader& r, Light& l) {
    static const char* known[] = {"type",      "position", "direction",  "color",
                                  "intensity", "range",    "inner_cone", "outer_cone"};
    if (!r.obj.is_object()) return r.fail("expected an object", nullptr);
    for (auto it = r.obj.begin(); it != r.obj.end(); ++it) {
        if (std::find_if(std::begin(known), std::end(known),
                         [&](const char* k) { return it.key() == k; }) == std::end(known))
            return r.fail("unknown field '" + it.key() + "'", nullptr);
    }
    if (!readType(r, l.type)) return false;
    const bool local = l.type != LightType::Directional, aimed = l.type != LightType::Point;
    bool ok = r.vec3("position", l.position, local) && r.vec3("direction", l.direction, aimed) &&
              r.vec3("color", l.color, false) && r.number("intensity", l.intensity, true, true) &&
              r.number("range", l.range, local, true) &&
              r.number("inner_cone", l.innerConeAngle, false, true) &&
              r.number("outer_cone", l.outerConeAngle, false, true);
    if (!ok) return false;
    if (glm::any(glm::lessThan(l.color, glm::vec3(0.0f))))
        return r.fail("must not be negative", "color");
    if (aimed && !(glm::length(glm::dvec3(l.direction)) >= kMinDirectionLength))
        return r.fail("must not be zero (length at least 1e-6)", "direction");
    if (local && !(l.range > 0.0f)) return r.fail("must be positive", "range");
    const double brightest = double(l.intensity) * std::max({l.color.r, l.color.g, l.color.b});
    const glm::dvec3 p = glm::abs(glm::dvec3(l.position));
    if (!r.atMost("position", std::max({p.x, p.y, p.z}), kMaxLightCoordinate,
                  "must be at most 1e10 in magnitude") ||
        !r.atMost("range", l.range, kMaxLightRange, "must be at most 1e10") ||
        !r.atMost("intensity", brightest, kMaxLightIntensity,
                  "intensity times the brightest color channel must be at most 1e15"))
        return false;
    if (l.innerConeAngle > l.outerConeAngle)
        return r.fail("inner_cone is larger than outer_cone", "inner_cone");
    if (l.outerConeAngle > 0.5f * kPi + 1e-6f) return r.fail("must be at most pi/2", "outer_cone");
    return true;
}

std::string oneLine(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    auto b = s.find("] ");
    if (s.rfind("[json.exception", 0) == 0 && b != std::string::npos) s = s.substr(b + 2);
    return s;
}

Result<std::vector<Light>> parseLights(const json& doc, const std::string& name) {
    auto err = [&](const std::string& what) { return Error{name + ": " + what}; };
    if (!doc.is_object()) return err("expected a JSON object with \"lights\" (at top level)");
    for (auto it = doc.begin(); it != doc.end(); ++it)
        if (it.key() != "version" && it.key() != "lights")
            return err("unknown field '" + it.key() + "' (at top level; valid: version, lights)");
    auto v = doc.find("version");
    if (v != doc.end() && !(v->is_number_integer() && v->get<int64_t>() == 1))
        return err("unsupported version, expected 1 (at version)");
    auto arr = doc.find("lights");
    if (arr == doc.end()) return err("missing field (at lights)");
    if (!arr->is_array()) return err("expected an array (at lights)");
    if (arr->size() > kMaxLights)
        return err(std::to_string(arr->size()) + " lights, at most " + std::to_string(kMaxLights) +
                   " (at lights)");
    std::vector<Light> lights(arr->size());
    for (size_t i = 0; i < arr->size(); ++i) {
        LightReader r{(*arr)[i], "lights[" + std::to_string(i) + "]", {}};
        if (!readLight(r, lights[i])) return err(r.error);
    }
    return lights;
}

} // namespace

std::string lightsToJson(const std::vector<Light>& lights) {
    // One light per line: diffable, and still small for 65,536 lights.
    std::string out = "{\"version\":1,\"lights\":[";
    for (size_t i = 0; i < lights.size(); ++i) {
        out += i ? ",\n  " : "\n  ";
        out += lightJson(lights[i]).dump();
    }
    out += lights.empty() ? "]}\n" : "\n]}\n";
    return out;
}

Result<std::vector<Light>> lightsFromJson(const std::string& text, const std::string& name) {
    Result<std::vector<Light>> lights = Error{""};
    try {
        json doc = json::parse(text);
        lights = parseLights(doc, name);
    } catch (const std::exception& e) {
        lights = Error{name + ": " + oneLine(e.what())};
    }
    // Messages quote the file's keys and strings: "int\nsity" must not break the line.
    if (!lights) return Error{printableLine(lights.error())};
    return lights;
}

Result<std::vector<Light>> readLightsFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        return Error{path + ": not a regular file"};
    if (uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > kMaxLightsFileBytes)
        return Error{path + ": " + std::to_string(size) + " bytes, over the " +
                     std::to_string(kMaxLightsFileBytes >> 20) + " MiB a lights file may have"};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{path + ": cannot open (" + std::strerror(errno) + ")"};
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return Error{path + ": read failed"};
    return lightsFromJson(text.str(), path);
}

Status writeLightsFile(const std::string& path, const std::vector<Light>& lights) {
    // Written beside and renamed, so a failed write never leaves a file that looks complete.
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) return Error{path + ": cannot write (" + std::strerror(errno) + ")"};
        out << lightsToJson(lights);
        out.flush();
        if (!out) {
            out.close();
            std::remove(tmp.c_str());
            return Error{path + ": write failed"};
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        return Error{path + ": cannot write (" + why + ")"};
    }
    return {};
}

} // namespace tp
