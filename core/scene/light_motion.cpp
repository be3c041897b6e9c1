// Seeded light motion (light_motion.h). Every number a light's motion uses comes from a hash
// of (seed, light index, which number), never from a generator stepped from light to light or
// frame to frame, so frame k of light i is the same whether computed alone or in sequence,
// and adding a light does not change the others' motion. Motions are offsets from the start
// position that are exactly zero at frame 0, computed in double.
#include "core/scene/light_motion.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace tp {
namespace {

constexpr double kMotionTwoPi = 6.283185307179586;

uint64_t motionMix(uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// A number in [0, 1) for (seed, light, stream).
double motionRandom(uint64_t seed, size_t light, uint64_t stream) {
    const uint64_t z = motionMix(seed ^ motionMix(uint64_t(light) * 64 + stream));
    return double(z >> 11) * (1.0 / 9007199254740992.0);
}

bool insideOnAxis(const Aabb& b, const glm::vec3& p, int axis) {
    return !b.empty() && p[axis] >= b.min[axis] && p[axis] <= b.max[axis];
}

// Largest radius of a circle through p, centred at p - r (c, s) in xz, that the bounds hold.
double orbitRoom(const Aabb& b, const glm::vec3& p, double c, double s) {
    double r = INFINITY;
    auto limit = [&](double below, double above, double dir) {
        // The circle spans p - r (dir + 1) .. p - r (dir - 1) along the axis.
        if (1.0 + dir > 0.0) r = std::min(r, below / (1.0 + dir));
        if (1.0 - dir > 0.0) r = std::min(r, above / (1.0 - dir));
    };
    limit(double(p.x) - b.min.x, double(b.max.x) - p.x, c);
    limit(double(p.z) - b.min.z, double(b.max.z) - p.z, s);
    return std::max(r, 0.0);
}

using Path = LightMotionPlan::Path;

Path orbitPath(const Light& light, size_t i, const LightMotion& m, const Aabb& bounds,
               double diagonal) {
    Path p;
    // A radius of 2 to 6 % of the scene's diagonal: 1.4 to 4 m in the courtyard.
    p.radius = diagonal * (0.02 + 0.04 * motionRandom(m.seed, i, 0));
    p.phase = kMotionTwoPi * motionRandom(m.seed, i, 1);
    const double sense = motionRandom(m.seed, i, 2) < 0.5 ? 1.0 : -1.0;
    p.cosPhase = std::cos(p.phase);
    p.sinPhase = std::sin(p.phase);
    if (insideOnAxis(bounds, light.position, 0) && insideOnAxis(bounds, light.position, 2))
        p.radius = std::min(p.radius, orbitRoom(bounds, light.position, p.cosPhase, p.sinPhase));
    p.moves = p.radius > 1e-9 * diagonal;
    p.rate = p.moves ? sense * double(m.speed) / p.radius : 0.0;
    return p;
}

Path driftPath(const Light& light, size_t i, const LightMotion& m, const Aabb& bounds,
               double diagonal) {
    // Three sines per axis with amplitudes in these proportions; each term's frequency is set
    // from its amplitude so that it adds at most 1/(3 sqrt 3) of `speed` per axis: the light's
    // step in a frame is at most `speed` in length.
    constexpr double kWeights[3] = {0.5, 0.3, 0.2};
    const double kPerTerm = 1.0 / (3.0 * std::sqrt(3.0));
    Path p;
    for (int axis = 0; axis < 3; ++axis) {
        if (!insideOnAxis(bounds, light.position, axis)) continue;
        const double at = light.position[axis];
        const double room = std::min(at - bounds.min[axis], double(bounds.max[axis]) - at);
        // 5 to 15 % of the bounds along the axis, halved to the room to the nearer side: the
        // sum of sin(w t + f) - sin(f) terms stays within twice the amplitude.
        const double extent = double(bounds.max[axis]) - bounds.min[axis];
        const double amplitude = std::min(
            extent * (0.05 + 0.10 * motionRandom(m.seed, i, 8 + uint64_t(axis))), 0.5 * room);
        if (!(amplitude > 1e-6 * diagonal)) continue;
        p.moves = true;
        for (int k = 0; k < 3; ++k) {
            const uint64_t stream = 16 + uint64_t(axis) * 8 + uint64_t(k) * 2;
            Path::Term& t = p.drift[axis][k];
            t.amplitude = amplitude * kWeights[k];
            const double w = kPerTerm * (0.5 + 0.5 * motionRandom(m.seed, i, stream)) / t.amplitude;
            t.rate = w * double(m.speed);
            t.phase = kMotionTwoPi * motionRandom(m.seed, i, stream + 1);
            t.sinPhase = std::sin(t.phase);
        }
    }
    return p;
}

glm::dvec3 offsetAt(const Path& p, LightMotion::Mode mode, uint32_t frame) {
    if (mode == LightMotion::Mode::Orbit) {
        const double angle = p.phase + p.rate * double(frame);
        return p.radius *
               glm::dvec3(std::cos(angle) - p.cosPhase, 0.0, std::sin(angle) - p.sinPhase);
    }
    glm::dvec3 offset(0.0);
    for (int axis = 0; axis < 3; ++axis)
        for (const Path::Term& t : p.drift[axis])
            if (t.amplitude > 0.0)
                offset[axis] +=
                    t.amplitude * (std::sin(t.rate * double(frame) + t.phase) - t.sinPhase);
    return offset;
}

} // namespace

Result<LightMotion> parseLightMotion(const std::string& text) {
    const size_t colon = text.find(':');
    const std::string name = text.substr(0, colon);
    LightMotion m;
    if (name == "none")
        m.mode = LightMotion::Mode::None;
    else if (name == "orbit")
        m.mode = LightMotion::Mode::Orbit;
    else if (name == "drift")
        m.mode = LightMotion::Mode::Drift;
    else
        return Error{printableLine("--light-motion: unknown mode \"" + name +
                                   "\" (valid: none, orbit, drift)")};
    if (colon == std::string::npos) {
        m.speed = m.mode == LightMotion::Mode::None ? 0.0f : kDefaultLightSpeed;
        return m;
    }
    const std::string speed = text.substr(colon + 1);
    if (m.mode == LightMotion::Mode::None)
        return Error{
            printableLine("--light-motion: \"none\" takes no speed (got \"" + text + "\")")};
    char* end = nullptr;
    const double v = speed.empty() ? NAN : std::strtod(speed.c_str(), &end);
    if (speed.empty() || end != speed.c_str() + speed.size() || !(v > 0.0) ||
        !(v <= double(kMaxLightSpeed)))
        return Error{printableLine("--light-motion: speed \"" + speed +
                                   "\" must be a number > 0 and at most 1e6 (scene units per "
                                   "frame)")};
    m.speed = float(v);
    return m;
}

std::string lightMotionToString(const LightMotion& motion) {
    if (motion.mode == LightMotion::Mode::None) return "none";
    char speed[32];
    const std::to_chars_result r = std::to_chars(speed, speed + sizeof speed, motion.speed);
    return std::string(motion.mode == LightMotion::Mode::Orbit ? "orbit:" : "drift:") +
           std::string(speed, r.ptr);
}

std::vector<Light> moveLights(const std::vector<Light>& start, const LightMotion& motion,
                              const Aabb& sceneBounds, uint32_t frame) {
    if (motion.mode == LightMotion::Mode::None || frame == 0) return start;
    return LightMotionPlan(start, motion, sceneBounds).at(frame);
}

LightMotionPlan::LightMotionPlan(const std::vector<Light>& start, const LightMotion& motion,
                                 const Aabb& sceneBounds)
    : start_(start), motion_(motion), bounds_(sceneBounds) {
    paths_.resize(start.size());
    if (motion.mode == LightMotion::Mode::None) return;
    const double diagonal = sceneBounds.empty() ? 1.0 : glm::length(sceneBounds.extent());
    for (size_t i = 0; i < start.size(); ++i)
        if (start[i].type != LightType::Directional)
            paths_[i] = motion.mode == LightMotion::Mode::Orbit
                            ? orbitPath(start[i], i, motion, sceneBounds, diagonal)
                            : driftPath(start[i], i, motion, sceneBounds, diagonal);
}

std::vector<Light> LightMotionPlan::at(uint32_t frame) const {
    std::vector<Light> lights = start_;
    if (motion_.mode == LightMotion::Mode::None || frame == 0) return lights;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (!paths_[i].moves) continue;
        Light& light = lights[i];
        const glm::dvec3 offset = offsetAt(paths_[i], motion_.mode, frame);
        glm::vec3 moved = glm::vec3(glm::dvec3(light.position) + offset);
        // The motions stay inside the bounds in exact arithmetic; rounding must not step out.
        for (int axis = 0; axis < 3; ++axis)
            if (insideOnAxis(bounds_, light.position, axis))
                moved[axis] = std::clamp(moved[axis], bounds_.min[axis], bounds_.max[axis]);
        light.position = moved;
    }
    return lights;
}

} // namespace tp
