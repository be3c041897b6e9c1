#pragma once
// The visibility buffer's knobs and the typed settings its passes read, turned from
// RenderSettings once in the factory (register.cpp builds the schema from the same
// declarations). The library's knobs (the light assignment's, the MSAA shading rate, the tiled
// lighting's radiance precision) and its own three: where blended surfaces are shaded, the
// size of the blended fragment lists and the texture footprint's derivatives.
#include "core/lightassign/knobs.h"
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/hdr_knob.h"
#include "core/renderer/knobs.h"
#include "core/renderer/msaa_knob.h"
#include "core/renderer/shadow_raster_knob.h"

namespace tp {
class GpuContext;
}

namespace tp::vis {

// --vis-blended: compute (per-pixel fragment lists composited in the resolve) or forward (the
// library's hybrid forward pass, as deferred's).
enum class Blended { Compute, Forward };
const ChoiceKnob<Blended>& blendedKnob();
// --vis-derivatives: the uv derivatives the resolve samples textures with. Analytic: the
// barycentrics' exact screen derivatives at the shaded location; Quad: the differences over
// the pixel's 2x2 quad on the same triangle's plane, as a fragment quad's helper lanes take
// them (coarse: resolveDerivatives); QuadFine / QuadCoarse: one of the two
// (docs/visbuffer.md, "The texture footprint").
enum class Derivatives { Quad, Analytic, QuadFine, QuadCoarse };
const ChoiceKnob<Derivatives>& derivativesKnob();
// The shader's mode (TP_VIS_DERIVATIVES_*) for `d`: Quad is coarse, as llvmpipe takes implicit
// derivatives (from the quad's top-left pixel, one level of detail per quad) and as measured
// closest to the reference on an NVIDIA H200 (docs/visbuffer.md, "The texture footprint").
uint32_t resolveDerivatives(Derivatives d);
// --vis-raster: who rasterizes the opaque and masked triangles into the visibility buffer.
// Hardware: the fixed-function visibility pass. Compute: every one in compute (vis_raster,
// vis_raster_big: visbuffer/raster_pass.h), merged into the same targets. Hybrid: the small
// opaque ones in compute, the large ones, those the near plane cuts and every masked draw by
// the hardware, into the same targets (docs/visbuffer.md, "The compute rasterizer"). Auto
// (the default, resolved by resolveRaster before the renderer plans): hybrid where it was
// measured faster, else hardware.
enum class Raster { Auto, Hardware, Compute, Hybrid };
const ChoiceKnob<Raster>& rasterKnob();
// --vis-edges: how the resolve lights its MSAA edge pixels at --msaa-shading pixel with
// --vis-blended compute. Pixel: one invocation an edge pixel, its surfaces lit and its blended
// fragments composited. Split: only the edges whose pixel has blended fragments so; the others
// flattened, a surface an invocation (as deferred's edges and --vis-blended forward's are).
// Auto: split on a GPU, pixel on a CPU device (resolveEdges; docs/visbuffer.md, "Edges with
// nothing to composite, flattened"). The same image whichever.
enum class Edges { Auto, Pixel, Split };
const ChoiceKnob<Edges>& edgesKnob();
// --vis-edges auto resolved on `ctx` (Pixel or Split; the others stay).
Edges resolveEdges(const GpuContext& ctx, Edges e);

// --vis-blended-capacity: the fragment pool in percent of the pixel count, 0: the derived
// bound (fragment_bound.h).
const IntegerKnob& blendedCapacityKnob();

// Blended fragments per pixel the compute resolve's lighting batches are sized for on a CPU
// device (core/passes/tiled_lighting.h: tiledLightBatch; lavapipe's loop limit): a pixel with
// more still composites all of them, and the most any pixel had is reported.
constexpr uint32_t kBlendedPerPixelBudget = 4;

struct Settings;
// --vis-raster auto resolved on `ctx`: hybrid on a GPU with the 64-bit atomics it needs, at 1x
// and without occlusion culling (whose late phase only the hardware pass draws), else
// hardware. H200, 1080p courtyard, 1,024 lights, 1x: frame 1.521 (hardware) against 1.462 ms
// (hybrid); at 4x hybrid is slower, and on lavapipe its visibility work is 4.5x the hardware's
// (docs/visbuffer.md, "The compute rasterizer"). Hardware, Compute and Hybrid stay.
Raster resolveRaster(const GpuContext& ctx, const Settings& s);

struct Settings {
    uint32_t width = 0, height = 0;
    Sampling sampling;
    bool debug = false;
    bool manyViews = false; // RenderSettings::manyViews: per-view lists get headroom
    la::AssignSettings assign;
    la::TileGroup tileGroup = la::TileGroup::Auto; // --tile-group
    HdrStorage hdr = HdrStorage::Fp32;
    Blended blended = Blended::Compute;
    Derivatives derivatives = Derivatives::Quad;
    uint32_t blendedCapacityPercent = 0; // 0: the derived bound
    CullGeometry cullGeometry = CullGeometry::None; // --cull-geometry: the visibility pass
    Raster raster = Raster::Auto;                   // --vis-raster (resolveRaster)
    Edges edges = Edges::Auto;                      // --vis-edges (resolveEdges)
    bool splitEdges() const { return edges == Edges::Split; } // after resolveEdges
    ShadowRaster shadowRaster = ShadowRaster::Hardware; // --shadow-raster: the atlas's faces
    // Many views: the blended fragments an earlier plan of this session overflowed with, times
    // two (RenderSettings::capacities[kSeenFragments]; Renderer contract step 7).
    uint64_t blendedSeen = 0;
    // Light evaluations per pixel and light of a batch the resolve may make: its samples, and
    // with `blendedBudget` (blended fragments composited in compute, on a CPU device) the
    // budgeted blended fragments (each sample's at the sample rate). Sizes the batches.
    uint32_t evaluationsPerPixel(bool blendedBudget) const;
};

inline constexpr const char* kSeenFragments = "visbuffer.blended_fragments";

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);

} // namespace tp::vis
