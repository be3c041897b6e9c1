#include "core/renderer/position_allowance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/camera/camera.h"
#include "core/camera/pixel_position.h"
#include "include/light_model.h"

namespace tp {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;
constexpr double kViewStep = 2.0; // degrees
constexpr int kViewBuckets = 45;  // 0 to 90 degrees

struct BrdfMaterial {
    float base, metallic, roughness;
    auto key() const { return std::tie(base, metallic, roughness); }
    bool operator<(const BrdfMaterial& o) const { return key() < o.key(); }
};

// Every (base, metallic, roughness) the scene can shade with; textures widen to the worst.
std::set<BrdfMaterial> materialsOf(const Scene& scene) {
    std::set<BrdfMaterial> out;
    for (const Material& m : scene.materials) {
        const float base =
            m.baseColorTexture != kNoTexture
                ? 1.0f
                : std::max({m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b});
        if (m.metallicRoughnessTexture != kNoTexture) {
            out.insert({base, 0.0f, TP_MIN_ROUGHNESS});
            out.insert({base, 1.0f, TP_MIN_ROUGHNESS});
        } else {
            out.insert({base, m.metallicFactor, m.roughnessFactor});
        }
    }
    return out;
}

glm::vec3 polar(double theta, double phi) {
    return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                     float(std::cos(theta)));
}

double brdfAt(const BrdfMaterial& m, glm::vec3 v, glm::vec3 l) {
    gpu::SurfaceSample s;
    s.position = gpu::vec3(0.0f);
    s.normal = gpu::vec3(0.0f, 0.0f, 1.0f);
    s.toViewer = gpu::vec3(v.x, v.y, v.z);
    s.baseColor = gpu::vec3(m.base);
    s.metallic = m.metallic;
    s.roughness = m.roughness;
    const gpu::vec3 f = gpu::brdfCos(s, gpu::vec3(l.x, l.y, l.z));
    return std::max({double(f.x), double(f.y), double(f.z)});
}

// Grows `limits` with one grid of light directions l(i, j) for view v: the values, and the
// change between neighbours in i and in j over the angle between them.
template <class LightDir>
void sampleGrid(BrdfLimits& limits, const BrdfMaterial& m, glm::vec3 v, int ni, int nj,
                LightDir lightDir) {
    std::vector<double> prev(size_t(nj), 0.0);
    std::vector<glm::vec3> prevL(static_cast<size_t>(nj));
    for (int i = 0; i < ni; ++i) {
        double left = 0;
        glm::vec3 leftL{};
        for (int j = 0; j < nj; ++j) {
            const glm::vec3 l = lightDir(i, j);
            const double f = brdfAt(m, v, l);
            limits.maxValue = std::max(limits.maxValue, f);
            auto slope = [&](double f2, glm::vec3 l2) {
                const double angle = std::acos(std::clamp(double(glm::dot(l, l2)), -1.0, 1.0));
                if (angle > 1e-7)
                    limits.lipschitz = std::max(limits.lipschitz, std::abs(f - f2) / angle);
            };
            if (i > 0) slope(prev[size_t(j)], prevL[size_t(j)]);
            if (j > 0) slope(left, leftL);
            left = f;
            leftL = l;
            prev[size_t(j)] = f;
            prevL[size_t(j)] = l;
        }
    }
}

// One limit per view angle bucket (kViewStep degrees from the normal), the bucket's two
// ends sampled.
std::vector<BrdfLimits> limitsOf(const BrdfMaterial& m) {
    std::vector<BrdfLimits> out(kViewBuckets);
    const double a = std::max(double(m.roughness), double(TP_MIN_ROUGHNESS));
    const double alpha = a * a;
    for (int iv = 0; iv <= kViewBuckets; ++iv) {
        const double thetaV = std::min(iv * kViewStep, 89.9) * kDegree;
        const glm::vec3 v = polar(thetaV, 0.0);
        BrdfLimits limits;
        // Light directions: the hemisphere at 1 degree x 3 degrees, then the specular lobe
        // (half vectors within 20 alpha of the normal at alpha/10 steps).
        sampleGrid(limits, m, v, 91, 61,
                   [](int i, int j) { return polar(i * kDegree, j * 3.0 * kDegree); });
        const double lobe = std::min(20.0 * alpha, 89.0 * kDegree);
        sampleGrid(limits, m, v, 201, 61, [&](int i, int j) {
            const glm::vec3 h = polar(lobe * i / 200.0, j * 3.0 * kDegree);
            return glm::reflect(-v, h);
        });
        // The view direction's own change (the viewer moves relative to the point too).
        const glm::vec3 v2 = polar(std::min(thetaV + 0.5 * kDegree, 89.95 * kDegree), 0.0);
        for (int il = 0; il < 90; il += 3) {
            const glm::vec3 l = polar(il * kDegree, 3.14159265358979323846);
            const double f0 = brdfAt(m, v, l), f1 = brdfAt(m, v2, l);
            const double angle = std::acos(std::clamp(double(glm::dot(v, v2)), -1.0, 1.0));
            if (angle > 1e-7)
                limits.lipschitz = std::max(limits.lipschitz, std::abs(f1 - f0) / angle);
        }
        for (int b : {iv - 1, iv}) // the sample is the upper end of bucket iv-1, the lower of iv
            if (b >= 0 && b < kViewBuckets) {
                out[size_t(b)].maxValue = std::max(out[size_t(b)].maxValue, limits.maxValue);
                out[size_t(b)].lipschitz = std::max(out[size_t(b)].lipschitz, limits.lipschitz);
            }
    }
    return out;
}

// limitsOf(m), computed once per material in this process: it is a pure function of the
// three numbers and costs ~0.1 s of CPU (the grids above, 46 view angles), and every error
// model asks for it, several times per image (each bound that walks the pixels, each pipeline
// of a compare, each case of stress: 60 % of the CPU of the visibility buffer's bound tests).
// The map only grows, and a reference into it stays valid (std::map never moves its nodes).
const std::vector<BrdfLimits>& limitsOfCached(const BrdfMaterial& m) {
    static std::mutex mutex;
    static std::map<BrdfMaterial, std::vector<BrdfLimits>> cache;
    {
        std::lock_guard<std::mutex> lock(mutex);
        auto it = cache.find(m);
        if (it != cache.end()) return it->second;
    }
    std::vector<BrdfLimits> limits = limitsOf(m); // outside the lock: threads compute in parallel
    std::lock_guard<std::mutex> lock(mutex);
    return cache.emplace(m, std::move(limits)).first->second;
}

// Gradient bound of one light's term at a point `d` from it (segment within `eps`), per
// unit of light intensity times colour, with the BRDF limits `b` and the point `eyeDistance`
// from the eye. Returns +Inf where the light may sit on the segment.
double lightGradientBound(const Light& light, double d, double eps, double eyeDistance,
                          const BrdfLimits& b) {
    const double dlo = d - 1.01 * eps;
    if (dlo <= 0.0) return std::numeric_limits<double>::infinity();
    const double m = std::max(dlo, double(TP_MIN_LIGHT_DISTANCE));
    const double r = light.range;
    // |d/dd (window / max(d, dmin)^2)| <= |window'| / m^2 + 2 / m^3, |window'| <= 2.42 / r.
    double attenuationGrad = 2.42 / (r * m * m) + 2.0 / (m * m * m);
    if (light.type == LightType::Spot) {
        const double spread =
            std::cos(double(light.innerConeAngle)) - std::cos(double(light.outerConeAngle));
        // The GPU's slope of the cone factor's ramp is 1 / max(kHardSpotSpread, spread).
        attenuationGrad += 2.0 / std::max(kHardSpotSpread, spread) / dlo / (m * m);
    }
    const double directionGrad = b.lipschitz * (1.0 / dlo + 1.0 / eyeDistance) / (m * m);
    return b.maxValue * attenuationGrad + directionGrad;
}

} // namespace

double snappedPositionPixels(uint32_t subPixelBits) {
    return std::sqrt(2.0) * std::ldexp(1.0, -int(subPixelBits) - 1);
}

std::vector<BrdfLimits> brdfLimits(const Scene& scene) {
    std::vector<BrdfLimits> all(kViewBuckets);
    for (const BrdfMaterial& m : materialsOf(scene)) {
        const std::vector<BrdfLimits>& one = limitsOfCached(m);
        for (size_t b = 0; b < all.size(); ++b) {
            all[b].maxValue = std::max(all[b].maxValue, 1.25 * one[b].maxValue);
            all[b].lipschitz = std::max(all[b].lipschitz, 1.25 * one[b].lipschitz);
        }
    }
    return all;
}

std::vector<glm::dvec3> pixelPositions(const Camera& cam, const ImageR32& depth) {
    const glm::dmat4 invViewProj = inverseShadingViewProjection(cam, depth.width, depth.height);
    std::vector<glm::dvec3> out(depth.r.size(),
                                glm::dvec3(std::numeric_limits<double>::quiet_NaN()));
    for (uint32_t y = 0; y < depth.height; ++y)
        for (uint32_t x = 0; x < depth.width; ++x) {
            const size_t i = size_t(y) * depth.width + x;
            if (depth.r[i] > 0.0f)
                out[i] =
                    pixelCentrePosition(invViewProj, depth.width, depth.height, x, y, depth.r[i]);
        }
    return out;
}

namespace {

// The surface of pixel (x, y) as its neighbours' positions span it: the step to the closer
// neighbour on each axis. False where that is not clear (sky next to it, or the two
// neighbours of an axis disagree: a depth edge).
bool neighbourAxes(const std::vector<glm::dvec3>& pos, const ImageR32& depth, uint32_t x,
                   uint32_t y, glm::dvec3& dx, glm::dvec3& dy) {
    auto at = [&](int xx, int yy) -> const glm::dvec3* {
        if (xx < 0 || yy < 0 || xx >= int(depth.width) || yy >= int(depth.height)) return nullptr;
        const glm::dvec3& q = pos[size_t(yy) * depth.width + size_t(xx)];
        return std::isnan(q.x) ? nullptr : &q;
    };
    const glm::dvec3 p = *at(int(x), int(y));
    auto axis = [&](int dx, int dy, glm::dvec3& d) {
        const glm::dvec3 *a = at(int(x) - dx, int(y) - dy), *b = at(int(x) + dx, int(y) + dy);
        if (!a || !b) return false;
        const glm::dvec3 da = p - *a, db = *b - p;
        const double la = glm::length(da), lb = glm::length(db);
        if (std::max(la, lb) > 1.5 * std::min(la, lb)) return false;
        d = la < lb ? da : db;
        return true;
    };
    return axis(1, 0, dx) && axis(0, 1, dy);
}

// The view-angle buckets [first, last] a pixel's surface may be in: from the normal of its
// neighbours' positions (neighbourAxes); every bucket where that is not clear.
std::pair<int, int> viewBuckets(const std::vector<glm::dvec3>& pos, const ImageR32& depth,
                                uint32_t x, uint32_t y) {
    const std::pair<int, int> all{0, kViewBuckets - 1};
    glm::dvec3 dx, dy;
    if (!neighbourAxes(pos, depth, x, y, dx, dy)) return all;
    const glm::dvec3 p = pos[size_t(y) * depth.width + x];
    const glm::dvec3 n = glm::cross(dx, dy);
    if (!(glm::length(n) > 0.0)) return all;
    const double cosV = std::abs(glm::dot(glm::normalize(n), glm::normalize(p)));
    const double theta = std::acos(std::clamp(cosV, 0.0, 1.0)) / kDegree;
    // One bucket either side: the neighbours' normal is not the exact normal at the centre.
    const int b = std::min(int(theta / kViewStep), kViewBuckets - 1);
    return {std::max(b - 1, 0), std::min(b + 1, kViewBuckets - 1)};
}

BrdfLimits limitsIn(const std::vector<BrdfLimits>& limits, std::pair<int, int> buckets) {
    BrdfLimits out;
    for (int b = buckets.first; b <= buckets.second; ++b) {
        out.maxValue = std::max(out.maxValue, limits[size_t(b)].maxValue);
        out.lipschitz = std::max(out.lipschitz, limits[size_t(b)].lipschitz);
    }
    return out;
}

// The scene's lights as both bounds read them, once per image rather than per pixel: the
// directional lights' summed strength (intensity times the largest colour channel), and each
// local light camera-relative with its strength.
struct LocalLight {
    const Light* light;
    glm::dvec3 position; // camera-relative
    double strength;
};
struct SplitLights {
    double directional = 0;
    std::vector<LocalLight> locals;
};
SplitLights splitLights(const Scene& scene) {
    SplitLights out;
    for (const Light& l : scene.lights) {
        const double strength = double(l.intensity) * std::max({l.color.r, l.color.g, l.color.b});
        if (l.type == LightType::Directional)
            out.directional += strength;
        else
            out.locals.push_back(
                {&l, glm::dvec3(l.position) - glm::dvec3(scene.camera.position), strength});
    }
    return out;
}

// Every pixel with geometry (pos: pixelPositions of depth): its coordinates, index,
// camera-relative point and the BRDF limits of its surface's view angle. Both per-pixel bounds
// walk the image this way.
template <class F>
void forEachSurfacePixel(const Scene& scene, const ImageR32& depth,
                         const std::vector<glm::dvec3>& pos, F&& f) {
    const std::vector<BrdfLimits> limits = brdfLimits(scene);
    for (uint32_t y = 0; y < depth.height; ++y)
        for (uint32_t x = 0; x < depth.width; ++x) {
            const size_t i = size_t(y) * depth.width + x;
            if (std::isnan(pos[i].x)) continue; // sky
            f(x, y, i, pos[i], limitsIn(limits, viewBuckets(pos, depth, x, y)));
        }
}

} // namespace

ImageR32 positionFromDepthAllowance(const Scene& scene, const ImageR32& depth,
                                    uint32_t subPixelBits, uint32_t samples) {
    ImageR32 out{depth.width, depth.height, std::vector<float>(depth.r.size(), 0.0f)};
    const Camera& cam = scene.camera;
    const glm::dmat4 view = viewRotation(cam);
    const glm::dmat4 inverse = inverseShadingViewProjection(cam, depth.width, depth.height);
    const double pixelPerDepth = 2.0 * std::tan(double(cam.yfov) * 0.5) / double(depth.height);
    const double epsPixels = snappedPositionPixels(subPixelBits);
    const std::vector<glm::dvec3> pos = pixelPositions(cam, depth);
    const SplitLights lights = splitLights(scene);
    // The allowance of a shaded point p (camera-relative) on a surface with BRDF limits b.
    auto allowanceAt = [&](const glm::dvec3& p, const BrdfLimits& b) {
        const double viewDepth = -(view * glm::dvec4(p, 1.0)).z;
        const double eps = epsPixels * pixelPerDepth * viewDepth;
        const double eyeDistance = glm::length(p);
        // Directional lights: only the view direction moves (by eps / eyeDistance).
        double allowance = lights.directional * b.lipschitz * eps / eyeDistance;
        for (const LocalLight& l : lights.locals) {
            const double d = glm::length(p - l.position);
            if (d >= double(l.light->range) + 1.01 * eps) continue;
            allowance += l.strength * eps * lightGradientBound(*l.light, d, eps, eyeDistance, b);
        }
        return allowance;
    };
    forEachSurfacePixel(scene, depth, pos, [&](uint32_t x, uint32_t y, size_t i,
                                               const glm::dvec3& p, const BrdfLimits& b) {
            double allowance = allowanceAt(p, b);
            // Under MSAA each sample is shaded at its own point: where the sample's ray meets
            // the plane the neighbours span (a light may reach a sample and no pixel centre).
            glm::dvec3 ax, ay;
            if (samples > 1 && neighbourAxes(pos, depth, x, y, ax, ay)) {
                const glm::dvec3 n = glm::cross(ax, ay);
                for (uint32_t s = 0; s < samples; ++s) {
                    const glm::dvec2 o = standardSampleOffset(samples, s);
                    const glm::dvec3 dir =
                        framebufferPosition(inverse, depth.width, depth.height, x + o.x, y + o.y, 1.0);
                    const double t = glm::dot(n, p) / glm::dot(n, dir);
                    if (std::isfinite(t) && t > 0) allowance = std::max(allowance, allowanceAt(t * dir, b));
                }
            }
            out.r[i] = float(allowance);
        });
    return out;
}

ReflectedLightBounds reflectedLightBounds(const Scene& scene, const ImageR32& depth) {
    ReflectedLightBounds out{{depth.width, depth.height, std::vector<float>(depth.r.size(), 0.0f)},
                             {depth.width, depth.height, std::vector<float>(depth.r.size(), 0.0f)}};
    const Camera& cam = scene.camera;
    const std::vector<glm::dvec3> pos = pixelPositions(cam, depth);
    const glm::dmat4 view = viewRotation(cam);
    const double pixelPerDepth = 2.0 * std::tan(double(cam.yfov) * 0.5) / double(depth.height);
    const SplitLights lights = splitLights(scene);
    forEachSurfacePixel(scene, depth, pos, [&](uint32_t, uint32_t, size_t i, const glm::dvec3& p,
                                               const BrdfLimits& b) {
            // A sample of the pixel lies within one pixel width of its centre's point.
            const double footprint = pixelPerDepth * -(view * glm::dvec4(p, 1.0)).z;
            // Sum of intensity * window / max(d, dmin)^2 (window <= 1).
            double light = lights.directional;
            for (const LocalLight& l : lights.locals) {
                const double d = glm::length(p - l.position);
                if (d >= double(l.light->range) + footprint) continue;
                const double m = std::max(d - footprint, double(TP_MIN_LIGHT_DISTANCE));
                light += l.strength / (m * m);
            }
            out.value.r[i] = float(light * b.maxValue);
            out.lipschitz.r[i] = float(light * b.lipschitz);
        });
    return out;
}

bool isHardSpot(const Light& light) {
    return light.type == LightType::Spot && light.outerConeAngle > 0.0f &&
           std::cos(double(light.innerConeAngle)) - std::cos(double(light.outerConeAngle)) <=
               kHardSpotSpread;
}

ImageR32 hardSpotEdgeAllowance(const Scene& scene, const ImageR32& depth, uint32_t samples) {
    std::vector<const Light*> spots;
    for (const Light& l : scene.lights)
        if (isHardSpot(l)) spots.push_back(&l);
    if (spots.empty()) return {};
    ImageR32 out{depth.width, depth.height, std::vector<float>(depth.r.size(), 0.0f)};
    const Camera& cam = scene.camera;
    const std::vector<glm::dvec3> pos = pixelPositions(cam, depth);
    const glm::dmat4 view = viewRotation(cam);
    const double pixelPerDepth = 2.0 * std::tan(double(cam.yfov) * 0.5) / double(depth.height);
    constexpr double kCosineRounding = 1e-5;
    Scene alone; // the spot by itself, with the scene's camera and materials
    alone.camera = cam;
    alone.materials = scene.materials;
    for (const Light* spot : spots) {
        const double cosOuter = std::cos(double(spot->outerConeAngle));
        const double spread = std::max(kHardSpotSpread, std::cos(double(spot->innerConeAngle)) - cosOuter);
        // The ramp [theta1, theta2] in angle from the axis, widened by the cosine's rounding.
        const double theta1 = std::acos(std::min(1.0, cosOuter + spread + kCosineRounding));
        const double theta2 = std::acos(std::max(-1.0, cosOuter - kCosineRounding));
        const glm::dvec3 apex = glm::dvec3(spot->position) - glm::dvec3(cam.position);
        const glm::dvec3 axis = glm::normalize(glm::dvec3(spot->direction));
        alone.lights = {*spot};
        const ImageR32 light = reflectedLightBounds(alone, depth).value;
        for (size_t i = 0; i < pos.size(); ++i) {
            if (std::isnan(pos[i].x) || light.r[i] == 0.0f) continue;
            const glm::dvec3 toPoint = pos[i] - apex;
            const double d = glm::length(toPoint);
            const double ball = pixelPerDepth * -(view * glm::dvec4(pos[i], 1.0)).z;
            bool straddles = d <= ball; // the ball holds the apex: every direction
            if (!straddles) {
                const double alpha = std::acos(std::clamp(glm::dot(toPoint, axis) / d, -1.0, 1.0));
                const double beta = std::asin(std::min(1.0, ball / d));
                straddles = alpha + beta >= theta1 && alpha - beta <= theta2;
            }
            if (straddles) out.r[i] += light.r[i];
        }
    }
    if (samples <= 1) return out;
    return maxOver3x3(out);
}

ImageR32 maxOver3x3(const ImageR32& a) {
    ImageR32 out = a;
    for (uint32_t y = 0; y < a.height; ++y)
        for (uint32_t x = 0; x < a.width; ++x) {
            float m = 0.0f;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int xx = int(x) + dx, yy = int(y) + dy;
                    if (xx >= 0 && yy >= 0 && xx < int(a.width) && yy < int(a.height))
                        m = std::max(m, a.r[size_t(yy) * a.width + size_t(xx)]);
                }
            out.r[size_t(y) * a.width + x] = m;
        }
    return out;
}

} // namespace tp
