#pragma once
// Multipass forward: the traditional forward renderer that Forward+ and deferred replaced.
//   depth_prepass  depth only (masked materials discard, blended ones absent)
//   base_pass      ambient + emissive + directional lights, depth EQUAL
//   light_passes   one additive pass per point/spot light over the meshes its sphere
//                  touches, scissored to its screen rectangle, depth EQUAL
//   blended        blended draws back to front: composite, then each light composited
//                  under the draw's own layers (exact for self-overlapping meshes)
// The accumulation target is RGBA16F or RGBA32F (the accum knob); MSAA shades per sample
// and resolves into hdr. See docs/multipass_forward.md.
#include <memory>

#include "core/renderer/renderer.h"

namespace tp {

std::unique_ptr<Renderer> createMultipassForwardRenderer(const RendererCreateInfo& info);

} // namespace tp
