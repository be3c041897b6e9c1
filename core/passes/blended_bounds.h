#pragma once
// Blended depth bounds: per tile, the nearest and farthest view distance of the blended
// fragments the blended shading pass will shade (include/light_assign.h: TP_LA_BLEND_*), so
// that a tile's transparent list (tiled) or front slices (clustered) cover only where its
// blended surfaces are, and a tile with none gets an empty transparent list. Used by Forward+
// (after the depth prepass) and deferred (after the G-buffer), before their culling.
//
// Two passes: "blended_bounds_clear" (transfer fill: min = +inf, max = 0) and
// "blended_bounds" (the blended draws, shaders/passes/blended_bounds.frag). Plan it only when the
// scene draws something blended; the buffer "blended_bounds" (2 words per tile) is in the
// ledger.
//
// With `opaque` the same passes ("centre_bounds_clear", "centre_bounds", buffer
// "centre_bounds") record the opaque and masked draws tested EQUAL against the prepass depth
// instead: the fragments an EQUAL-tested shading pass shades. Forward+ plans it at
// --msaa-shading pixel under MSAA, where a fragment is shaded once at the pixel centre with its
// inputs extrapolated along its triangle's plane when the centre lies off the triangle: a point
// that can lie nearer or farther than every depth the tile's samples store, so the tile's
// opaque range must take these distances too (issue 40, item 7).
#include <cstdint>

#include "core/gpu/descriptors.h"
#include "core/gpu/frame_graph.h"
#include "core/lightassign/tile_grid.h"

namespace tp {

class GpuContext;
class SceneGpu;

namespace la {

// What the blended shading pass does, which the bounds pass must repeat to see the same
// fragments at the same positions.
struct BlendedBoundsConfig {
    TileGrid grid;
    ResourceHandle depth; // the opaque depth the blended pass tests against (per sample under MSAA)
    uint32_t samples = 1; // its sample count
    bool sampleShading = false; // the blended pass shades per sample
    bool inputsAtPixel = false; // its fragment inputs are TP_INPUTS_AT_PIXEL (scene_inputs.glsl)
    // The opaque and masked draws, depth EQUAL (the prepass's depth), instead of the blended
    // ones, depth GREATER (header comment).
    bool opaque = false;
    // Tests only: draw with the whole scene.vert interface (every output and input) instead
    // of its position-only variant, to check that the variant records the same bounds.
    bool fullInterface = false;
    // Another pass draws the same blended draws with the same state and records the bounds
    // in its fragment shader (shaders/passes/blended_bounds.glsl): the visibility buffer's
    // blended lists. Only the buffer and its clear are planned. Possible only where the
    // fragments are per pixel: see fusable().
    bool drawnElsewhere = false;
    // Tests only: one atomic pair per fragment even where the device reduces per subgroup
    // (GpuContext::reducesFragmentsBySubgroup, TP_LA_SPEC_BLEND_BY_SUBGROUP: shaders/passes/
    // blended_bounds.glsl's kBySubgroup), to check that the reduction records the same bounds.
    bool perFragmentAtomics = false;

    // Whether a pass that runs once per pixel and primitive (no sample shading) sees exactly
    // these fragments at these positions: at 1x, and under MSAA when the bounds are taken once
    // per pixel at its centre. drawnElsewhere requires it.
    bool fusable() const { return !opaque && (samples == 1 || (inputsAtPixel && !sampleShading)); }
    // The variant of blended_bounds.glsl's inputs such a pass compiles: "_pixel" or "".
    const char* inputsSuffix() const { return inputsAtPixel ? "_pixel" : ""; }
};

class BlendedBounds {
  public:
    BlendedBounds(GpuContext& ctx, SceneGpu& scene) : ctx_(ctx), scene_(scene) {}
    ~BlendedBounds();
    BlendedBounds(const BlendedBounds&) = delete;
    BlendedBounds& operator=(const BlendedBounds&) = delete;

    // Declares the buffer and both passes; returns the buffer (read by the culling).
    ResourceHandle plan(FrameGraph& graph, const BlendedBoundsConfig& config);
    void prepare(FrameGraph& graph);
    ResourceHandle buffer() const { return bounds_; }

  private:
    void record(PassContext& pc);

    GpuContext& ctx_;
    SceneGpu& scene_;
    BlendedBoundsConfig config_;
    ResourceHandle bounds_;
    PassSet set_;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// Reads back a bounds buffer: per tile, whether it has a blended fragment and its
// unpadded [min, max] view distance (tests and statistics).
struct TileBlendedBounds {
    bool any = false;
    float nearDist = 0.0f, farDist = 0.0f;
};
std::vector<TileBlendedBounds> unpackBlendedBounds(const std::vector<uint8_t>& bytes,
                                                   uint32_t tiles);

} // namespace la
} // namespace tp
