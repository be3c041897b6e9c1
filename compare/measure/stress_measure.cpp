// Figures and verdicts of one pipeline in one stress case.
#include "compare/measure/stress_measure.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "compare/measure/stress_shadows.h"
#include "core/image/tonemap.h"

namespace tp::cli {
namespace {

bool hasCounter(const RunResult& run, const std::string& name) {
    return !std::isnan(counterValue(run, name, NAN));
}

bool fp16Hdr(const RunResult& run) {
    for (const LedgerEntry& e : run.memory)
        if (e.tag.name == "hdr" && e.format == VK_FORMAT_R16G16B16A16_SFLOAT) return true;
    return false;
}

// Where the reference exceeds 65,504 and the pipeline stores fp16, the channel cannot be
// represented: classify what the pipeline wrote and take it out of the error bound by
// copying the reference's value (both images, before the tonemap).
ImageRGBA maskOverflow(StressOutcome& p, const ImageRGBA& ref) {
    ImageRGBA checked = p.run->hdr;
    for (size_t i = 0; i < ref.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c) {
            const size_t k = i * 4 + c;
            if (!(ref.rgba[k] > kHalfMax)) continue;
            ++p.overflowChannels;
            if (!p.fp16Storage) continue;
            const float v = p.run->hdr.rgba[k];
            if (std::isinf(v) && v > 0)
                ++p.overflowInf;
            else if (v >= kHalfMax * (1.0f - 1.0f / 1024.0f) && v <= kHalfMax)
                ++p.saturated;
            else
                continue; // anything else (NaN included) stays in the comparison
            checked.rgba[k] = ref.rgba[k];
        }
    return checked;
}

// Inf pixels the overflow rule does not explain: an Inf (or NaN) that spread.
uint64_t unexplainedInf(const StressOutcome& p, const ImageRGBA& ref) {
    uint64_t n = 0;
    for (size_t i = 0; i < ref.pixelCount(); ++i) {
        bool bad = false;
        for (int c = 0; c < 3; ++c) {
            const float v = p.run->hdr.rgba[i * 4 + c];
            bad |= std::isinf(v) && !(p.fp16Storage && ref.rgba[i * 4 + c] > kHalfMax && v > 0);
        }
        n += bad;
    }
    return n;
}

// Worst (|p - r| less the pixel's allowance) / (relative * |r| + absolute) over the pixels
// and RGB channels of `checked` (fp16-overflow channels already set to the reference's
// values): the bound itself, checked on HDR values. Pixels with a +Inf allowance are left
// out (counted by errorBeyondAllowance); a NaN difference gives +Inf.
double hdrBeyondBound(const ErrorBound& b, const ImageRGBA& checked, const ImageRGBA& ref) {
    const bool perPixel = b.perPixel.radiance.r.size() == ref.pixelCount();
    double worst = 0;
    for (size_t i = 0; i < ref.pixelCount(); ++i) {
        const double allowance = perPixel ? double(b.perPixel.radiance.r[i]) : 0.0;
        if (std::isinf(allowance)) continue;
        for (int c = 0; c < 3; ++c) {
            const double r = ref.rgba[i * 4 + c], d = std::abs(double(checked.rgba[i * 4 + c]) - r);
            if (std::isnan(d)) return INFINITY;
            worst = std::max(worst, std::max(d - allowance, 0.0) /
                                        (b.relative() * std::abs(r) + b.absolute()));
        }
    }
    return worst;
}

uint64_t depthMismatch(const ImageR32& a, const ImageR32& b) {
    if (a.r.size() != b.r.size()) return a.r.size() + b.r.size();
    uint64_t n = 0;
    for (size_t i = 0; i < a.r.size(); ++i)
        n += a.r[i] != b.r[i];
    return n;
}

void addChecks(StressOutcome& p, const StressCaseResult& r, const ImageRGBA& ref,
               const Scene& scene, const RenderSettings& settings) {
    auto check = [&](std::string name, double measured, double limit, std::string why) {
        p.checks.push_back({std::move(name), measured <= limit, measured, limit, std::move(why)});
    };
    check("NaN pixels", double(p.nanPixels), 0, "no NaN may appear, let alone spread");
    check("Inf pixels not explained by fp16 overflow", double(unexplainedInf(p, ref)), 0,
          "+Inf only where the reference exceeds 65,504 and the target is fp16");
    check("lights dropped", p.lightsDropped, 0, "the default list layouts never drop a light");
    if (p.bound.bounded)
        check(p.bound.perPixel.name.empty()
                  ? "tonemapped max |p - r|"
                  : "tonemapped max |p - r| beyond the per-pixel allowance",
              p.checkedMaxTonemapped, p.bound.tonemapped(r.exposureEv),
              "the pipeline's derived bound (relative " + std::to_string(p.bound.relative()) +
                  ", absolute " + std::to_string(p.bound.absolute()) + ") through the tonemap" +
                  (p.bound.perPixel.name.empty()
                       ? ""
                       : "; each pixel's limit widened by " + p.bound.perPixel.name));
    if (p.bound.bounded && !p.bound.perPixel.name.empty())
        check("pixels the per-pixel allowance leaves unchecked", double(p.unboundedPixels), 0,
              "a light within the position error of a shaded point bounds nothing there; no case "
              "may have one "
              "unnoticed");
    if (p.bound.bounded && r.c->hdrChecked)
        check("HDR max |p - r| / (relative |r| + absolute)", p.hdrBeyondBound, 1,
              "the bound itself on linear values, per pixel and channel (less the per-pixel "
              "allowance where the "
              "model has one): the case's values span more than the tonemap shows at one exposure");
    if (p.inertChecked)
        check("pixels the inert lights change", double(p.inertChanged), 0,
              "the last " + std::to_string(r.c->inertLights) +
                  " lights must contribute exactly nothing: the image "
                  "equals bit for bit this renderer's image of the scene with their intensity 0");
    if (r.c->depthExact)
        check("depth pixels differing from the reference", double(p.depthMismatch), 0,
              "same triangles, same vertex shader (precise gl_Position), D32 reverse-Z");
    const RendererEntry& entry = **findRenderer(p.name);
    const std::vector<stress::CounterAtLeast> stressed =
        entry.stressedCounters ? entry.stressedCounters({*r.c, scene, settings})
                               : std::vector<stress::CounterAtLeast>{};
    for (const stress::CounterAtLeast& s : stressed) {
        if (!hasCounter(*p.run, s.counter)) continue;
        const double v = counterValue(*p.run, s.counter, 0);
        p.checks.push_back({"stressed: " + s.counter, v >= s.atLeast, v, s.atLeast, s.why});
    }
    if (r.c->shadows.enabled()) p.checks.push_back(shadowedLightsCheck(*p.run, *r.c));
}

} // namespace

uint64_t bitDifferentPixels(const ImageRGBA& a, const ImageRGBA& b) {
    if (a.rgba.size() != b.rgba.size()) return std::max(a.pixelCount(), b.pixelCount());
    uint64_t n = 0;
    for (size_t i = 0; i < a.pixelCount(); ++i)
        n += std::memcmp(&a.rgba[i * 4], &b.rgba[i * 4], 3 * sizeof(float)) != 0;
    return n;
}

void countNonFinite(const ImageRGBA& image, uint64_t& nanPixels, uint64_t& infPixels) {
    nanPixels = infPixels = 0;
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        bool nan = false, inf = false;
        for (int c = 0; c < 3; ++c) {
            nan |= std::isnan(image.rgba[i * 4 + c]);
            inf |= std::isinf(image.rgba[i * 4 + c]);
        }
        nanPixels += nan;
        infPixels += inf && !nan;
    }
}

void measureOutcome(StressOutcome& p, const StressOutcome& reference, const StressCaseResult& r,
                    const Scene& scene) {
    const ImageRGBA& ref = reference.run->hdr;
    MetricsOptions hdrOptions;
    float peak = 1.0f;
    for (size_t i = 0; i < ref.pixelCount(); ++i)
        for (int c = 0; c < 3; ++c)
            if (std::isfinite(ref.rgba[i * 4 + c])) peak = std::max(peak, ref.rgba[i * 4 + c]);
    hdrOptions.psnrPeak = peak;
    const ImageRGBA refDisplay = tonemapToDisplay(ref, r.exposureEv);
    p.hdr = computeError(p.run->hdr, ref, hdrOptions);
    p.display = computeError(tonemapToDisplay(p.run->hdr, r.exposureEv), refDisplay);
    countNonFinite(p.run->hdr, p.nanPixels, p.infPixels);
    p.fp16Storage = fp16Hdr(*p.run);
    p.lightsDropped = counterValue(*p.run, "lights_dropped", 0);
    p.depthMismatch = depthMismatch(p.run->depth, reference.run->depth);
    const RendererEntry& entry = **findRenderer(p.name);
    RenderSettings settings =
        r.settings; // as the run saw it: its knobs' defaults filled in (it ran, so they are valid)
    resolveKnobs(entry.knobs, settings);
    p.bound = expectedBound(entry.errorModel, {*r.c, scene, settings, &reference.run->depth,
                                               r.subPixelBits, &reference.run->hdr});
    const ImageRGBA checked = maskOverflow(p, ref);
    p.rawMaxTonemapped = computeError(tonemapToDisplay(checked, r.exposureEv), refDisplay).maxAbs;
    const AllowanceCheck beyond = errorBeyondAllowance(p.bound, checked, ref, r.exposureEv);
    p.checkedMaxTonemapped = beyond.worstBeyond;
    if (r.c->hdrChecked) p.hdrBeyondBound = hdrBeyondBound(p.bound, checked, ref);
    p.allowancePixels += beyond.widenedPixels;
    p.unboundedPixels += beyond.unboundedPixels;
    addChecks(p, r, ref, scene, settings);
    p.pass = true;
    for (const StressCheck& c : p.checks)
        p.pass &= c.pass;
}

std::string overflowBehaviour(const StressOutcome& p) {
    if (!p.run || p.overflowChannels == 0) return "no value beyond 65,504";
    if (!p.fp16Storage) return "fp32 target: values beyond 65,504 kept";
    std::string s;
    if (p.saturated) s += "saturates at 65,504 (" + std::to_string(p.saturated) + " channels)";
    if (p.overflowInf)
        s += std::string(s.empty() ? "" : "; ") + "overflows to +Inf (" +
             std::to_string(p.overflowInf) + " channels)";
    const uint64_t other = p.overflowChannels - p.saturated - p.overflowInf;
    if (other)
        s += std::string(s.empty() ? "" : "; ") + std::to_string(other) +
             " channels neither (checked against the bound)";
    return s;
}

} // namespace tp::cli
