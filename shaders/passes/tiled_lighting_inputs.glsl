// The tiled lighting pass of the pass library (core/passes/tiled_lighting.h), part 1 of 4: its
// inputs, before the surface source's reader. A pipeline's entry shader is
//   #include "passes/tiled_lighting_inputs.glsl"   // this: the scene, the light model, shadows
//   #include "<its surface reader>"                 // e.g. deferred/gbuffer_read.glsl
//   #include "passes/tiled_lighting_shade.glsl"    // the tile's lists, shade() and writeHdr()
//   #include "<its pixel>"                          // passes/tiled_lighting_pixel.glsl, or its own
//   #include "passes/tiled_lighting_main.glsl"     // culling, ordered lists, main
// and the pass's variant matrix is made by triptych_tiled_lighting_variants
// (passes/tiled_lighting.cmake). The order of the parts is the order of the declarations
// in the SPIR-V, so it stays as it is.
//
// The surface reader interface (core/passes/tiled_lighting.h: SurfaceSource binds its
// resources at set TP_SET_PASS; the reader declares them and these):
//   const uint kSamples, const bool kEverySample      spec constants TP_SPEC_SAMPLES, TP_TL_SPEC_EVERY_SAMPLE
//   float fetchDepth(ivec2 p, uint s)                  sample s's depth (0: no geometry)
//   float meanDepth(ivec2 p)                           the samples' mean depth (a one-surface pixel)
//   bool isEdge(ivec2 p)                               the samples hold different surfaces (MSAA)
//   vec2 sampleOffset(uint s)                          sample s's position in the pixel
//   SurfaceSample readSurfaceAt(ivec2 p, uint s, vec2 offset, float depth)   the lit surface
//   vec3 ambientEmissive(ivec2 p, uint s)              the light-independent term (first batch)
//   vec2 debugRoughMetal(ivec2 p)                      TP_DEBUG: roughness and metallic
// A reader that composites blended fragments in the pass (the visibility buffer's
// --vis-blended compute) defines TP_TL_COMPOSITES_BLENDED: the pass then keeps shading a
// tile with blended fragments in later batches and makes the transparent list visible to
// its own invocations.
//
// What the pass does, and its variant defines:

// Tiled deferred lighting (Andersson 2009, Uncharted; Lauritzen 2010): one workgroup per
// tile. (1) the tile's depth bounds over every sample of the surface's depth (reduced by the
// tile_depth_bounds pass before this one, core/passes/tile_depth_bounds.h), (2) the lights
// of this dispatch's batch (push constant: [first, end), at most the shared capacity) that
// reach the tile's sub-frustum are culled into a shared list, in ascending candidate order
// (compactList: the same list, and so the same opaque lighting, on every run), (3) every pixel of the tile
// is shaded from that list: the first batch writes hdr (with ambient and emissive), later
// batches add to it. Under MSAA a pixel whose samples differ (an edge) is shaded per
// sample, every other pixel once. Blended scenes also get each tile's transparent light
// list (every light, first batch only), culled against the tile's blended depth bounds
// (include/light_assign.glsl: LaBlendedBounds; empty where no blended fragment is shaded),
// in ascending candidate order too (a bitmask over the candidates, or cullTransparentIndices),
// stored in the compact layout of
// include/light_assign.h: per-tile runs sized on the CPU by a conservative bound, so the
// buffer grows with the lights the lists can hold, never with tiles x lights.
//   TP_EMISSIVE (0/1): the surface has an emissive target (the G-buffer's).
//   TP_MSAA: the surface is per-sample.  TP_HDR_MSAA: hdr is per-sample (the blended
//   forward pass draws into it and resolves).  TP_TRANSPARENT: write transparent lists.
//   TP_DEBUG: write the edge mask, roughness and metallic.  TP_HDR16: hdr is RGBA16F.
//   TP_LISTS_ONLY: only the transparent lists and tile statistics (volumes lighting
//   shades the opaque surfaces; the hybrid forward pass still needs the lists).
//   TP_SHADOW_MAPS (the _shadow twins, --shadows): every light's term (and the composited
//   blended fragments') times its visibility in the shadow atlas (include/shadow_light.glsl).
#include "include/shared.h"
#include "passes/tiled_lighting.h"
#include "include/scene_bindings.glsl"
#include "include/light_model.h"
// evalLightShadowed: evalLight itself, or (TP_SHADOW_MAPS, the _shadow twins) times the
// light's visibility in the shadow atlas (set TP_SET_SHADOW).
#include "include/shadow_light.glsl"
// The lights' uniform-buffer copy (include/lights_ubo.h: a CPU device, where a storage-buffer
// load branches per lane): every light of the pass's loops through sceneLight.
#define TP_LIGHTS_UBO_BINDING TP_TL_BINDING_LIGHTS_UBO
#define TP_LIGHTS_UBO_SPEC TP_TL_SPEC_LIGHTS_UBO
#include "include/lights_ubo.glsl"
#ifdef TP_LISTS_ONLY
#define TP_SURFACE_DEPTH_ONLY
#endif
