#pragma once
// `--cull-geometry none|frustum|full`: whether a pipeline's geometry passes draw the scene's meshes
// whole (none, the default: the images of a build without meshlet culling, bit for bit) or
// the meshlets a compute pass kept (frustum: bounding sphere against the view's planes and
// the normal cone against the eye; core/passes/meshlet_cull.h, docs/geometry.md). Declared
// here, once, for every pipeline that routes its geometry through the cull pass (Forward+,
// deferred, the visibility buffer, multipass forward: each lists it in its schema; the
// reference stays brute force). full: frustum and cone, then occlusion against a depth pyramid
// in two phases (last frame's visible meshlets drawn first, the pyramid built from their depth,
// the rest tested against it and drawn: core/passes/depth_pyramid.h).
#include "core/renderer/knobs.h"

namespace tp {

enum class CullGeometry { None, Frustum, Full };
const ChoiceKnob<CullGeometry>& cullGeometryKnob();

} // namespace tp
