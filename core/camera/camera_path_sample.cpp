// Sampling a keyframed camera path (camera_path.h): even view times over the keys' times,
// positions and targets on a linear or centripetal Catmull-Rom curve, the rest linear.
//
// Why centripetal (alpha = 1/2, Yuksel, Schaefer and Keyser 2011) and not uniform: camera
// bookmarks are placed by hand, so a short hop (a step through a doorway) often sits beside a
// long flight; uniform Catmull-Rom overshoots there and can loop, swinging the camera through
// a wall, while the centripetal curve is proven free of cusps and self-intersections within
// a segment and stays close to its chords. It is evaluated in Hermite form, which gives the
// key itself (not a rounded sum of it) at a segment's ends.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "core/camera/camera_file.h"
#include "core/camera/camera_path.h"

namespace tp {
namespace {

using glm::dvec3;

// Time of view i of n over [t0, t1]: exact at both ends, and exact wherever it falls on an
// integer when the times are integers (the keys of a path with default times).
double pathViewTime(double t0, double t1, uint32_t i, uint32_t n) {
    if (n == 1) return t0;
    return (t0 * double(n - 1 - i) + t1 * double(i)) / double(n - 1);
}

// (b - a) / dt, which tends to zero with |b - a| when dt is its square root: zero for equal
// points (a key repeated to hold the camera still), not 0/0.
dvec3 pathChordRate(const dvec3& a, const dvec3& b, double dt) {
    return dt > 0.0 ? (b - a) / dt : dvec3(0.0);
}

// Centripetal Catmull-Rom viewBetween p1 and p2 (p0 and p3 their neighbours), s in [0, 1]: the
// tangents of the Barry-Goldman pyramid with knot intervals |p[i+1] - p[i]|^(1/2), in
// Hermite form.
dvec3 centripetalPoint(const dvec3& p0, const dvec3& p1, const dvec3& p2, const dvec3& p3,
                       double s) {
    const double d01 = std::sqrt(glm::length(p1 - p0));
    const double d12 = std::sqrt(glm::length(p2 - p1));
    const double d23 = std::sqrt(glm::length(p3 - p2));
    if (d12 == 0.0) return p1; // the point holds still over this segment
    const dvec3 m1 =
        pathChordRate(p0, p1, d01) - pathChordRate(p0, p2, d01 + d12) + (p2 - p1) / d12;
    const dvec3 m2 =
        (p2 - p1) / d12 - pathChordRate(p1, p3, d12 + d23) + pathChordRate(p2, p3, d23);
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s;
    const double h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
    return h00 * p1 + h10 * d12 * m1 + h01 * p2 + h11 * d12 * m2;
}

// The curve through points[k] .. points[k + 1]; an end segment mirrors its end point's
// neighbour, so the path leaves its first key (and reaches its last) along the chord.
dvec3 pathCurvePoint(const std::vector<dvec3>& points, size_t k, double s,
                     Interpolation interpolation) {
    const dvec3& p1 = points[k];
    const dvec3& p2 = points[k + 1];
    if (interpolation == Interpolation::Linear) return (1.0 - s) * p1 + s * p2;
    const dvec3 p0 = k > 0 ? points[k - 1] : 2.0 * p1 - p2;
    const dvec3 p3 = k + 2 < points.size() ? points[k + 2] : 2.0 * p2 - p1;
    return centripetalPoint(p0, p1, p2, p3, s);
}

double pathLerp(double a, double b, double s) {
    return (1.0 - s) * a + s * b;
}

struct KeyTrack {
    std::vector<dvec3> positions, targets;
};

// The view at segment k, fraction s in (0, 1).
Camera viewBetween(const std::vector<Camera>& keys, const KeyTrack& track, size_t k, double s,
                   Interpolation interpolation) {
    const Camera& a = keys[k];
    const Camera& b = keys[k + 1];
    Camera c;
    c.position = glm::vec3(pathCurvePoint(track.positions, k, s, interpolation));
    c.target = glm::vec3(pathCurvePoint(track.targets, k, s, interpolation));
    c.up = glm::vec3((1.0 - s) * dvec3(a.up) + s * dvec3(b.up));
    c.yfov = float(pathLerp(a.yfov, b.yfov, s));
    c.znear = float(pathLerp(a.znear, b.znear, s));
    // Between a finite and an infinite far plane there is no far plane to blend: infinite.
    c.zfar = a.zfar > 0.0f && b.zfar > 0.0f ? float(pathLerp(a.zfar, b.zfar, s)) : 0.0f;
    return c;
}

} // namespace

const char* interpolationName(Interpolation interpolation) {
    return interpolation == Interpolation::Linear ? "linear" : "catmull-rom";
}

Result<std::vector<Camera>> sampleCameraPath(const std::vector<Camera>& keys,
                                             const std::vector<double>& times, uint32_t frames,
                                             Interpolation interpolation,
                                             const std::string& where) {
    if (keys.empty() || times.size() != keys.size())
        return Error{where + ": a camera path needs at least one key, each with a time"};
    if (frames < 1 || frames > kMaxPathFrames)
        return Error{where + ": \"frames\" must be from 1 to " + std::to_string(kMaxPathFrames) +
                     " (got " + std::to_string(frames) + ")"};
    for (size_t k = 0; k < times.size(); ++k)
        if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1])))
            return Error{where + ": key " + std::to_string(k) +
                         ": times must be finite and strictly increasing"};
    KeyTrack track;
    for (const Camera& key : keys) {
        track.positions.push_back(dvec3(key.position));
        track.targets.push_back(dvec3(key.target));
    }
    std::vector<Camera> views;
    views.reserve(frames);
    for (uint32_t i = 0; i < frames; ++i) {
        const double t = pathViewTime(times.front(), times.back(), i, frames);
        // The last key whose time is not after t.
        size_t k = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
        k = k == 0 ? 0 : k - 1;
        Camera view = times[k] == t || k + 1 == keys.size()
                          ? keys[k]
                          : viewBetween(keys, track, k, (t - times[k]) / (times[k + 1] - times[k]),
                                        interpolation);
        // Checked as a camera file is; the JSON round trip gives back exactly these floats.
        Result<Camera> checked =
            cameraFromJson(cameraToJson(view), where + ": view " + std::to_string(i));
        if (!checked) return Error{checked.error()};
        views.push_back(*checked);
    }
    return views;
}

} // namespace tp
