#pragma once
// Forward+ (tiled forward shading; AMD ForwardPlus11, Harada et al. 2012):
//   depth_prepass      depth only; masked draws discard, blended draws are not in it
//   node_counter_reset "linked" layout only: the node pool's allocation counter to 0
//   light_culling      compute, one 64-invocation workgroup per tile: depth bounds over every
//   sample,
//                      point/spot lights against the tile sub-frustum, lists written out
//   forward_opaque     opaque + masked draws, depth test EQUAL, no discard, tile list loop
//   forward_transparent blended draws back to front with the transparent list (only when
//                      the scene has blended materials)
// Publishes "hdr" (resolved; RGBA16F, or RGBA32F under --hdr fp32) and "depth". See
// docs/forwardplus.md.
// The renderer orchestrates; fp_config.h resolves the settings against the device and the
// scene (and lists what that leaves out), light_culling.h records the culling pass,
// light_lists.h sizes the lists, core/lightassign/light_bins.h bins the lights (shared with
// tiled deferred).
#include <memory>

#include "core/renderer/renderer.h"

namespace tp {

std::unique_ptr<Renderer> createForwardPlusRenderer(const RendererCreateInfo& info);

} // namespace tp
