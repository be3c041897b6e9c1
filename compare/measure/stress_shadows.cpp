// The shadow technique's verdict in the shadowed stress cases: the reference on the shadow
// maps against the ray-traced one, per the case's facts (stress::ShadowFacts). Each bound is
// derived in docs/stress.md, "Shadowed cases", from include/shadows.h: the texel footprint at
// axis distance d is params.x * d (params.x = 2 tan(fov/2) / edge), the receiver moves
// TP_SHADOW_NORMAL_OFFSET footprints along its normal and is compared TP_SHADOW_DEPTH_BIAS
// footprints nearer, the PCF reads the (2r + 1)^2 texels around the nearest one.
#include "compare/measure/stress_shadows.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/cli/shadow_option.h"
#include "core/util/number_text.h"
#include "core/image/tonemap.h"
#include "core/reference/reference_renderer.h"
#include "core/renderer/position_allowance.h"
#include "core/renderer/renderer.h"

namespace tp::cli {
namespace {

constexpr double kTaps = (2 * TP_SHADOW_PCF_RADIUS + 1) * (2 * TP_SHADOW_PCF_RADIUS + 1);
// The two references are one shader but for the visibility: their light terms agree within
// the error models' "same code, other shader" term.
constexpr double kSameRelative = 1e-5, kSameAbsolute = 1e-7;
constexpr double kOnPlane = 1e-3; // m: a pixel's point (from the depth) lies on the floor

double rgb(const ImageRGBA& im, size_t i) {
    return double(im.rgba[i * 4]) + double(im.rgba[i * 4 + 1]) + double(im.rgba[i * 4 + 2]);
}

bool onFloor(const glm::dvec3& p) {
    return std::abs(p.y) < kOnPlane; // false for NaN (sky)
}

// More light in the maps image than the rays one: light the maps let through an occluder.
bool leaks(double maps, double rays) {
    return !(maps <= rays * (1 + kSameRelative) + kSameAbsolute);
}

void check(ShadowTechnique& t, std::string name, double measured, double limit, std::string why) {
    t.checks.push_back({std::move(name), measured <= limit, measured, limit, std::move(why)});
}

void atLeast(ShadowTechnique& t, std::string name, double measured, double limit, std::string why) {
    t.checks.push_back(
        {"stressed: " + std::move(name), measured >= limit, measured, limit, std::move(why)});
}

const ShadowLight* planned(const ShadowPlan& plan, int light) {
    for (const ShadowLight& l : plan.lights)
        if (int(l.light) == light) return &l;
    return nullptr;
}

// Acne: on a plane the light sees, the nearest texel's depth differs from the receiver's by
// up to half a texel's span and a PCF tap's by 1.5 spans; the normal offset (1.5 footprints)
// moves the lookup that far toward the light, so no tap sees the plane nearer than the
// receiver, and the bias (1 footprint) puts it a footprint beyond the tie. Expected: no tap
// lost; the limit allows one (a tie decided by rounding), the PCF's 1/9 step.
void acneChecks(ShadowTechnique& t, const ImageRGBA& maps, const ImageRGBA& rays,
                const std::vector<glm::dvec3>& world) {
    double worst = 0;
    uint64_t lit = 0;
    for (size_t i = 0; i < world.size(); ++i) {
        const double r = rgb(rays, i);
        if (!onFloor(world[i]) || !(r > 1e-30)) continue;
        ++lit;
        const double darker = (r - rgb(maps, i)) / r; // the share of the light the maps took
        if (!(darker <= worst)) worst = darker;       // NaN propagates
    }
    atLeast(t, "floor pixels the rays see lit", double(lit), 1,
            "the case must put lit receivers under the acne check");
    check(t, "acne: largest share of its light the maps take from a floor pixel the rays see lit",
          worst, 1.0 / kTaps + kSameRelative,
          "one PCF tap of " + std::to_string(int(kTaps)) +
              " (the derivation expects none: the normal offset of 1.5 footprints carries the "
              "lookup past the half texel and the tap radius, the bias a footprint beyond the "
              "tie), plus the references' same-code term");
}

// Peter-panning and leaks behind a wall facing the spot's axis (its front face at axis
// distance D, thickness w, covering the whole cone): every texel that sees the wall stores D,
// every other tap of a receiver behind it sees the floor in front (nearer). A receiver on the
// floor at axis distance X (the floor's normal offset is across the axis: X unchanged) is
// compared at X (1 - b p), so the maps light it exactly where X (1 - b p) <= D: the band
// D b p / (1 - b p) - w behind the back face, none if negative (b: the depth bias in
// footprints; the offset and the PCF radius add nothing here). The leak check takes the general
// band, where the offset and the tap reach count too (a wall at any angle): k = offset + bias +
// radius footprints.
void wallChecks(ShadowTechnique& t, const ImageRGBA& maps, const ImageRGBA& rays,
                const std::vector<glm::dvec3>& world, const Scene& scene, const ShadowPlan& plan,
                const stress::ShadowFacts& f) {
    const ShadowLight* sl = planned(plan, f.wallLight);
    atLeast(t, "the wall's spot light has a shadow map", sl ? 1 : 0, 1,
            "the plan must shadow the light the wall stands in front of");
    if (!sl) return;
    const double p = plan.faces[sl->firstFace].params.x;
    const double D = double(scene.lights[size_t(f.wallLight)].position.z) - f.wallFront;
    const double w = double(f.wallFront) - f.wallBack;
    const double b = TP_SHADOW_DEPTH_BIAS;
    const double k = TP_SHADOW_NORMAL_OFFSET + TP_SHADOW_DEPTH_BIAS + TP_SHADOW_PCF_RADIUS;
    // A band narrower than the wall is none: the receiver behind it is never lit.
    const double band = std::max(0.0, D * b * p / (1 - b * p) - w);
    const double general = std::max(0.0, D * k * p / (1 - k * p) - w);
    constexpr double kSlack = 1e-4; // m: rounding of depths and positions (a pixel is ~1 cm)
    uint64_t behind = 0, beyond = 0;
    double widest = 0;
    for (size_t i = 0; i < world.size(); ++i) {
        if (!onFloor(world[i]) || !(world[i].z < f.wallBack)) continue;
        ++behind;
        if (!leaks(rgb(maps, i), rgb(rays, i))) continue;
        const double depth = double(f.wallBack) - world[i].z;
        widest = std::max(widest, depth);
        beyond += depth > general;
    }
    atLeast(t, "floor pixels behind the wall", double(behind), 1,
            "the eye must see the floor the wall shadows");
    const std::string footprint = "the footprint at the wall p D = " + formatNumber(p * D) +
                                  " m (p = " + formatNumber(p) + ", D = " + formatNumber(D) +
                                  " m), the wall " + formatNumber(w) + " m thick";
    check(t, "light leaks: floor pixels lit behind the wall beyond the general band",
          double(beyond), 0,
          "beyond " + formatNumber(general) +
              " m (offset + bias + PCF radius = " + formatNumber(k) +
              " footprints, less the wall) the maps must shadow the floor as "
              "the rays do; " +
              footprint);
    check(t, "peter-panning: widest lit band behind the wall (m)", widest, band + kSlack,
          "the depth bias's " + formatNumber(b) + " footprint(s) at the receiver, less the wall: " +
              formatNumber(band) + " m, + 0.1 mm for rounding; " + footprint);
}

// A closed box around a point light: every direction from it meets the box first, so nothing
// outside may be lit by it (each image equals its image with that light at intensity 0: the
// runner's inert-light twin), and its receivers outside must fall in all six cube faces.
void boxChecks(ShadowTechnique& t, const StressCaseResult& r, const std::vector<glm::dvec3>& world,
               const Scene& scene, const stress::ShadowFacts& f) {
    check(t, "light in the box: pixels it lights outside, maps reference",
          double(r.reference.inertChanged), 0,
          "all six faces of its cube map must hold the box: a pixel that changes with the "
          "light's intensity saw it through a gap");
    check(t, "light in the box: pixels it lights outside, rays reference",
          double(t.rays.inertChanged), 0, "every shadow ray from outside meets the closed box");
    const Light& light = scene.lights[size_t(f.boxLight)];
    const glm::dvec3 lo = glm::dvec3(f.boxLo) - 0.01, hi = glm::dvec3(f.boxHi) + 0.01;
    std::array<uint64_t, 6> perFace{};
    for (const glm::dvec3& p : world) {
        if (std::isnan(p.x)) continue;
        if (glm::all(glm::greaterThan(p, lo)) && glm::all(glm::lessThan(p, hi))) continue;
        const glm::dvec3 d = p - glm::dvec3(light.position), a = glm::abs(d);
        if (!(glm::length(d) < light.range)) continue;
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
        ++perFace[size_t(2 * axis + (d[axis] >= 0 ? 0 : 1))];
    }
    double faces = 0;
    for (uint64_t n : perFace)
        faces += n > 0;
    atLeast(t, "cube faces of the light in the box with receivers in its range outside", faces, 6,
            "every face of the cube map must stand between the light and a pixel the eye sees");
}

} // namespace

std::string missingShadowReferences() {
    Result<const RendererEntry*> ref = findRenderer(kReferenceRenderer);
    if (!ref) return ref.error();
    for (const Knob& k : (*ref)->knobs) {
        if (k.name != kReferenceShadowsKnob) continue;
        const auto has = [&](const char* v) {
            return std::find(k.values.begin(), k.values.end(), v) != k.values.end();
        };
        if (has(kReferenceShadowMaps) && has(kReferenceShadowRays)) return "";
    }
    return "this build's reference has no --reference-shadows maps and rays: a shadowed case "
           "needs both";
}

RenderSettings withReferenceShadows(RenderSettings s, const char* value) {
    s.set(kReferenceShadowsKnob, value);
    return s;
}

void measureShadowTechnique(StressCaseResult& r, const Scene& scene, const ShadowPlan& plan) {
    ShadowTechnique& t = *r.shadow;
    const stress::ShadowFacts& f = r.c->shadowFacts;
    t.checks.clear();
    atLeast(t, "lights the plan shadows", double(plan.lights.size()), f.shadowedLights,
            "--shadows " + shadowCountText(r.c->shadows) + " must shadow the case's lights");
    if (!t.rays.run || t.rays.nanPixels + t.rays.infPixels) {
        t.checks.push_back({"ran", false, 0, 1,
                            t.rays.run ? "the rays reference has NaN/Inf pixels"
                                       : "the rays reference failed: " + t.rays.error});
        t.pass = false;
        return;
    }
    const ImageRGBA &maps = r.reference.run->hdr, &rays = t.rays.run->hdr;
    t.hdr = computeError(maps, rays);
    t.display =
        computeError(tonemapToDisplay(maps, r.exposureEv), tonemapToDisplay(rays, r.exposureEv));
    std::vector<glm::dvec3> world = pixelPositions(scene.camera, r.reference.run->depth);
    for (glm::dvec3& p : world)
        p += glm::dvec3(scene.camera.position);
    if (f.floorAcne) acneChecks(t, maps, rays, world);
    if (f.wallLight >= 0) wallChecks(t, maps, rays, world, scene, plan, f);
    if (f.boxLight >= 0) boxChecks(t, r, world, scene, f);
    t.pass = true;
    for (const StressCheck& c : t.checks)
        t.pass &= c.pass;
}

StressCheck shadowedLightsCheck(const RunResult& run, const stress::StressCase& c) {
    const double v = counterValue(run, "shadowed_lights", 0);
    const double want = c.shadowFacts.shadowedLights;
    return {"stressed: shadowed_lights", v >= want, v, want,
            "the pipeline renders and samples the maps of every light the plan shadows "
            "(ShadowMaps::counters); a pipeline without the counter ignored --shadows"};
}

} // namespace tp::cli
