#include "visbuffer/error_model.h"

#include <algorithm>
#include <string>

#include "core/passes/tiled_lighting.h"
#include "core/renderer/msaa_knob.h"
#include "core/renderer/position_allowance.h"
#include "visbuffer/lod_allowance.h"
#include "visbuffer/vis_settings.h"

namespace tp {
namespace {

bool hasBlended(const Scene& scene) {
    return std::any_of(scene.materials.begin(), scene.materials.end(),
                       [](const Material& m) { return m.alphaMode == AlphaMode::Blend; });
}

// --hdr fp16: one rounding per lighting batch (a later batch loads the rounded sum, adds and
// stores again), and the resolve of hdr_msaa (blended scenes under MSAA).
void addHdrStorage(ErrorBound& b, const ErrorModelInput& in) {
    const vis::Settings s = vis::readSettings(in.settings);
    if (s.hdr != HdrStorage::Fp16) return;
    // The smaller batch of a CPU device (more batches, more roundings): a bound for both.
    const bool blended = hasBlended(in.scene);
    uint32_t batch = tiledLightBatch(s.assign.tile, s.evaluationsPerPixel(blended));
    if (s.assign.clustered())
        batch = std::min(batch, TP_TL_CLUSTER_MASK_WORDS * 32 / s.assign.slices);
    const uint32_t lights = uint32_t(in.scene.lights.size());
    int stores = int(std::max(1u, (lights + batch - 1) / batch));
    std::string what = "one per lighting batch of " + std::to_string(batch) + " lights";
    if (s.sampling.msaa() && blended && s.blended == vis::Blended::Forward) {
        stores += 1;
        what += ", resolve";
    }
    addFp16StorageTerm(b, stores, what);
}

} // namespace

void visbufferErrorModel(ErrorBound& b, const ErrorModelInput& in) {
    // The resolve intersects the ray through the sample location with the triangle as the
    // scene gives it; the rasterizer (and so the reference) interpolates with barycentrics of
    // vertices snapped to its sub-pixel grid: the two shaded points lie up to
    // sqrt(2) * 2^-(bits + 1) pixel widths apart on the surface, deferred's displacement
    // (core/renderer/position_allowance.h), with the same per-pixel bound next to lights.
    // Textures: sampled with the analytic derivatives or the quad's differences
    // (--vis-derivatives), the reference's with the hardware's (lod_allowance.h bounds either:
    // the model does not know the device's fine or coarse rule); the two allowances add.
    if (in.referenceDepth) {
        ImageR32 allowance =
            positionFromDepthAllowance(in.scene, *in.referenceDepth, in.subPixelBits,
                                       in.settings.msaa);
        const ImageR32 lod =
            vis::textureLodAllowance(in.scene, *in.referenceDepth, in.referenceHdr);
        for (size_t i = 0; i < allowance.r.size(); ++i)
            allowance.r[i] += lod.r[i];
        // Under MSAA a resolved pixel averages its samples, which may lie on other surfaces
        // than the reference depth's sample 0 (or on geometry where sample 0 has none): each
        // such surface holds sample 0 of this pixel or of a neighbour unless it is thinner
        // than a pixel, so the pixel takes the largest allowance of its 3x3 neighbourhood.
        if (in.settings.msaa > 1) allowance = maxOver3x3(allowance);
        b.perPixel = {"exact hit next to lights, texture level of detail",
                      "the shaded point is the exact hit at the sample location, the reference's "
                      "the point of the triangle snapped to 2^-" +
                          std::to_string(in.subPixelBits) +
                          " pixel: up to sqrt(2) * 2^-(bits + 1) pixel widths apart (per pixel, "
                          "that times a bound on the gradient of every light term reaching it); "
                          "plus the level-of-detail change times the textures' ranges and the "
                          "radiance's sensitivity to them (docs/visbuffer.md)",
                      std::move(allowance)};
    }
    b.terms.push_back({"barycentrics from the ray-plane hit", 1e-6, 0,
                       "the hit and its barycentrics in fp32 from camera-relative vertices: a "
                       "few ulps of each interpolated attribute"});
    // Under --msaa-shading pixel, a pixel is shaded once per triangle at its centre, as
    // Forward+'s and the blended pass's fragments are: the same centre-shading term.
    addPixelRateErrorTerm(b, in);
    addHdrStorage(b, in);
    // Blended layers: --vis-blended compute composites them in the resolve's fp32 registers and
    // stores the pixel with its batch (addHdrStorage's stores); forward blends each into hdr_msaa
    // (hdr at 1x) and stores it there.
    const vis::Settings s = vis::readSettings(in.settings);
    const bool forward = s.blended == vis::Blended::Forward;
    addBlendedLayersTerm(b, in, 1, forward && s.hdr == HdrStorage::Fp16,
                         forward ? "each blended with all its lights by the hybrid forward pass"
                                 : "each composited in the resolve's registers");
}

} // namespace tp
