#pragma once
// What `triptych stress` expects of a pipeline in a case: a per-pixel error bound against
// the reference derived from how the pipeline computes (storage formats, summation,
// G-buffer quantization), never from what it printed. The generic terms are here; each
// pipeline adds its own from its folder (RendererEntry::errorModel). docs/stress.md
// explains each term.
//
// The bound is |pipeline - reference| <= relative * |reference| + absolute per HDR channel.
// The verdict checks it on tonemapped values (what a user sees, and where a relative bound
// stays meaningful next to black pixels): the tonemap T (one exposure for both images)
// changes by at most K * relative + S0 * 2^ev * absolute, with
//   K  = sup_x x * T'(x)  (a relative change of x moves T by at most K times it),
//   S0 = sup_x T'(x)      (an absolute change of x moves T by at most S0 times it),
// both computed here from the tonemap operator itself (shaders/include/tonemap.h).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/image/image.h"
#include "core/renderer/settings.h"
#include "core/scene/scene.h"
#include "core/scene/stress_scenes.h"

namespace tp {

struct ErrorModelInput;

struct BoundTerm {
    std::string name;
    double relative = 0;
    double absolute = 0;
    std::string why;
};

// An allowance that depends on where a pixel is (e.g. next to a light), on top of the
// uniform terms: per pixel, the largest |pipeline - reference| in HDR radiance (any
// channel) it explains; +Inf where the model bounds nothing at that pixel. The verdict
// widens each pixel's tonemapped limit by what this radiance moves the tonemap there.
struct PixelAllowance {
    std::string name; // empty: none
    std::string why;
    ImageR32 radiance;
};

struct ErrorBound {
    bool bounded = true; // false: the method gives no per-pixel bound here (`why` says so)
    std::string why;
    std::vector<BoundTerm> terms;
    PixelAllowance perPixel;
    double relative() const;
    double absolute() const;
    // Largest allowed |T(pipeline) - T(reference)| per channel at exposure `ev`.
    double tonemapped(float ev) const;
};

// A pipeline's image checked against the bound with each pixel's allowance (ErrorBound::
// perPixel) taken out: what `triptych stress` and the GPU tests compare with tonemapped().
struct AllowanceCheck {
    // max over pixels and channels of |T(p) - T(r)| less what the pixel's allowance explains
    // there (pixels with a +Inf allowance left out); +Inf as soon as a channel differs by NaN.
    double worstBeyond = 0;
    uint64_t widenedPixels = 0;   // allowance > 0: the limit there was widened
    uint64_t unboundedPixels = 0; // allowance +Inf: nothing is checked there
    size_t worstPixel = 0;        // where worstBeyond is (row-major), for a failure's message
};

// `pipeline` and `reference` are HDR images of the same size, tonemapped at `ev` here. With
// no per-pixel allowance (or one of another size) worstBeyond is the plain max |T(p) - T(r)|.
AllowanceCheck errorBeyondAllowance(const ErrorBound& bound, const ImageRGBA& pipeline,
                                    const ImageRGBA& reference, float ev);

// Rounding units the pipelines' models are written in.
constexpr double kHalfUlp16 = 1.0 / 1024.0; // fp16 store: below one ulp, 2^-10 relative
constexpr double kUlp32 = 1.0 / 16777216.0; // 2^-24

// Colour stored in an RGBA16F target `roundings` times on its way to readback (`stores` names
// them, e.g. "sample, resolve"): each store is below one ulp, 2^-10 relative (Vulkan allows
// rounding toward zero), 6e-8 absolute in the subnormals. Every pipeline with an fp16 colour
// target adds this one term (Forward+ always; deferred under --hdr fp16).
void addFp16StorageTerm(ErrorBound& b, int roundings, const std::string& stores);

// Blended layers (StressCase::blendedLayers = L over one pixel; nothing when 0): the composite
// goes through B = L * blendsPerLayer blends at most in the pipeline (1 per layer where a
// layer is shaded with all its lights in one draw; 1 + its lights where each light is blended
// onto it in a draw of its own) and through L in the reference. Each blend rounds at most 4
// times in fp32 (src * a, 1 - a, dst * (1 - a), the sum), each relative to a value whose weight
// in the final pixel is at most the pixel (weights are products of alphas and 1 - alpha, all in
// [0, 1], and every term is non-negative): 4 * (B + L) * 2^-24. `fp16Store`: each blend's
// result is stored in an RGBA16F target (the blend unit's storage; fp32 blend arithmetic
// assumed, Vulkan only requires the destination's precision): once more each, B * (2^-10
// relative, 6e-8 absolute). `how` says what a layer's blends are. docs/stress.md.
void addBlendedLayersTerm(ErrorBound& b, const ErrorModelInput& in, uint32_t blendsPerLayer,
                          bool fp16Store, const std::string& how);

// K and S0 of the header comment, from the tonemap at exposure 0 (K does not depend on
// exposure; S0 scales with 2^ev).
double tonemapRelativeSlope();
double tonemapAbsoluteSlope();

struct ErrorModelInput {
    const stress::StressCase& stressCase;
    const Scene& scene;
    const RenderSettings& settings; // knobs resolved
    // What the device and the reference run add for models that need them (may be absent).
    const ImageR32* referenceDepth = nullptr; // the reference's published D32 reverse-Z depth
    uint32_t subPixelBits = 8;                // VkPhysicalDeviceLimits::subPixelPrecisionBits
    const ImageRGBA* referenceHdr = nullptr;  // the reference's image (radiance per pixel)
};

// Adds the pipeline's own terms to `bound` (or marks it unbounded with the reason).
using ErrorModel = std::function<void(ErrorBound& bound, const ErrorModelInput& in)>;
// The counters a case must drive up for this pipeline, as configured, to have stressed what
// the case claims.
using StressedCounters =
    std::function<std::vector<stress::CounterAtLeast>(const ErrorModelInput& in)>;

// The bound for a pipeline with model `model` (may be empty: a generic two-fp16-roundings
// model) in a case: the shared terms (summation, same code in another shader) plus its own.
ErrorBound expectedBound(const ErrorModel& model, const ErrorModelInput& in);

} // namespace tp
