#pragma once
// Which lights cast shadows and how big their maps are (docs/shadows.md): a CPU plan (what it
// holds: core/gpuscene/shadow_plan.h) from the camera-relative lights and frame the shaders
// get, the same for every pipeline and the reference of a run, so they all shadow the same
// lights with the same maps.
//
//   selection   --shadows N: the N lights with the largest screen-space influence (the pixels
//               their range sphere's screen rectangle covers, clipped to the view); `all`: every
//               light that reaches the view. Directional lights cast none (no cascades yet).
//   faces       a point light (or a spot whose cone is wider than kMaxSpotHalfAngle) gets six
//               90-degree cube faces, a spot one face over its cone.
//   resolution  per light from its screen size: the face edge is the square root of its
//               influence (halved for a cube's faces), a power of two in [kMinEdge, kMaxEdge]; over
//               --shadow-budget, the largest maps are halved (the least influential first) until
//               the atlas fits; a budget that cannot hold every face at kMinEdge is an error.
//   atlas       every face a power-of-two square, packed largest first along a Z-order curve
//               into a power-of-two atlas (no gaps: each offset is a multiple of the next area).
//   local       one light's faces in a 3 x 2 block: the map a per-light pipeline renders, samples
//               and renders over again for the next light (deferred volumes, multipass).
#include <cstdint>
#include <vector>

#include "core/gpuscene/shadow_plan.h"
#include "core/scene/shadow_settings.h"
#include "include/shadows.h"

namespace tp {

class SceneGpu;

constexpr uint32_t kShadowMinEdge = 16;
constexpr uint32_t kShadowMaxEdge = 2048;
constexpr float kShadowNear = 1e-3f;          // 1 mm: nearer occluders are clipped
constexpr float kMaxSpotHalfAngle = 1.0472f;  // 60 degrees: a wider spot is shadowed as a cube

// `lights` and `frame` as uploaded (camera-relative); `width`/`height` the view. ShadowError
// (core/scene/shadow_settings.h) when the budget cannot hold the lights.
ShadowPlan planShadows(const std::vector<gpu::LightGpu>& lights, const gpu::FrameUniforms& frame,
                       uint32_t width, uint32_t height, const ShadowSettings& settings,
                       uint32_t maxImageDimension);

// The same for the scene's current view and lights as uploaded (SceneGpu::shadingLights,
// shadingFrame): what the frame runner gives the scene before each render.
ShadowPlan planShadows(const SceneGpu& scene, const ShadowSettings& settings,
                       uint32_t maxImageDimension);

} // namespace tp
