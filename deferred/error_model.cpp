#include "deferred/error_model.h"

#include <algorithm>
#include <cmath>

#include "core/passes/tiled_lighting.h"
#include "core/renderer/msaa_knob.h"
#include "core/renderer/position_allowance.h"
#include "deferred/def_settings.h"
#include "deferred/deferred_shared.h"
#include "include/light_model.h"
#include "include/tonemap.h"

namespace tp {
namespace {

// Smallest non-zero base colour channel among the materials: 8-bit sRGB moves it most.
float darkestBase(const Scene& scene) {
    float d = 1.0f;
    for (const Material& m : scene.materials)
        for (int c = 0; c < 3; ++c)
            if (m.baseColorFactor[c] > 0.0f) d = std::min(d, m.baseColorFactor[c]);
    return d;
}

// Smallest roughness that 8 bits cannot hold exactly (values at or below the clamp 0.03 on
// both sides of the rounding, and multiples of 1/255, come back unchanged); 0 when none.
float inexactRoughness(const Scene& scene) {
    float r = 0.0f;
    for (const Material& m : scene.materials) {
        float q = std::round(m.roughnessFactor * 255.0f) / 255.0f;
        if (q == m.roughnessFactor) continue;
        if (std::max(q, m.roughnessFactor) <= TP_MIN_ROUGHNESS) continue;
        float eff = std::max(m.roughnessFactor, TP_MIN_ROUGHNESS);
        if (r == 0.0f || eff < r) r = eff;
    }
    return r;
}

void addCompactGBuffer(ErrorBound& b, const ErrorModelInput& in) {
    const float d = darkestBase(in.scene);
    const double srgb = gpu::srgbEncode(d);
    b.terms.push_back(
        {"8-bit sRGB base colour", 2.4 * (0.5 / 255.0) / (srgb + 0.055), 0,
         "2.4 * (0.5/255) / (s + 0.055) at the darkest base channel " + std::to_string(d)});
    const float r = inexactRoughness(in.scene);
    if (r > 0.0f)
        b.terms.push_back({"8-bit roughness", 6.0 * (0.5 / 255.0) / r, 0,
                           "6 * (0.5/255) / r at r = " + std::to_string(r) +
                               " (|dlnD/dlnr| <= 4, |dlnVis/dlnr| <= 2)"});
    if (in.stressCase.freeNormals)
        b.terms.push_back(
            {"octahedral normals", 6.5e-5 * 10.0, 0,
             "RG16_SNORM octahedral normals move <= 6.5e-5 rad; times |tan| <= 10 of the light "
             "angle where n.l >= 0.1"});
}

bool hasBlended(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (m.alphaMode == AlphaMode::Blend) return true;
    return false;
}

// --hdr fp16: hdr (and hdr_msaa) are RGBA16F, with Forward+'s term for its RGBA16F target:
// one rounding per store a pixel's sum goes through. Tiled: one per lighting batch (a later
// batch loads the rounded sum, adds and stores again); volumes: the base pass and one blend
// per light; then the resolve of hdr_msaa (blended scenes under MSAA). As for Forward+, each
// blended layer's store adds one more: addBlendedLayersTerm in deferredErrorModel.
void addHdrStorage(ErrorBound& b, const ErrorModelInput& in) {
    const def::Settings s = def::readSettings(in.settings);
    if (s.hdr != def::Hdr::Fp16) return;
    const uint32_t lights = uint32_t(in.scene.lights.size());
    int stores = 0;
    std::string what;
    if (s.lighting == def::Lighting::Volumes) {
        stores = 1 + int(lights);
        what = "base pass, one blend per light volume";
    } else {
        uint32_t batch = tiledLightBatch(s.assign.tile, s.sampling.samples);
        if (s.assign.clustered())
            batch = std::min(batch, TP_TL_CLUSTER_MASK_WORDS * 32 / s.assign.slices);
        stores = int(std::max(1u, (lights + batch - 1) / batch));
        what = "one per lighting batch of " + std::to_string(batch) + " lights";
    }
    if (s.sampling.msaa() && hasBlended(in.scene)) {
        stores += 1;
        what += ", resolve";
    }
    addFp16StorageTerm(b, stores, what);
}

} // namespace

void deferredErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    b.terms.push_back(
        {"position from depth", 2.5e-4, 2.5e-8,
         "positions reconstructed from D32 depth with the inverse view-projection, fp32 sums in "
         "tile order: docs/deferred.md's per-pixel bound (2.5e-4 of |r| + 1e-4)"});
    if (in.referenceDepth)
        b.perPixel = {
            "position from depth next to lights",
            "the reconstructed point is up to sqrt(2) * 2^-(" + std::to_string(in.subPixelBits) +
                " + 1) pixel widths off the shaded surface (vertex snapping before the depth "
                "plane); "
                "per pixel, that times a bound on the gradient of every light term reaching it",
            positionFromDepthAllowance(in.scene, *in.referenceDepth, in.subPixelBits)};
    if (def::readSettings(in.settings).gbuffer == def::GBuffer::Compact) addCompactGBuffer(b, in);
    // Under --msaa-shading pixel, non-edge pixels lit once at the centre (the Lauritzen path)
    // and blended surfaces shaded once at the centre (the hybrid forward pass, as Forward+'s
    // and multipass's): the same centre-shading term, since a blend of non-negative layers keeps
    // the relative bound of each. Nothing at 1x or at the sample rate, where every sample is
    // shaded at itself.
    addPixelRateErrorTerm(b, in);
    addHdrStorage(b, in);
    // The hybrid forward pass blends each layer, with all its lights, into hdr (hdr_msaa).
    addBlendedLayersTerm(b, in, 1, def::readSettings(in.settings).hdr == def::Hdr::Fp16,
                         "each blended with all its lights by the hybrid forward pass");
}

} // namespace tp
