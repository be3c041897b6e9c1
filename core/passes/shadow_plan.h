#pragma once
// Which lights cast shadows and how big their maps are (docs/shadows.md): a CPU plan from the
// camera-relative lights and frame the shaders get, the same for every pipeline and the
// reference of a run, so they all shadow the same lights with the same maps.
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
#include <stdexcept>
#include <string>
#include <vector>

#include "core/render/settings.h"
#include "include/shadows.h"

namespace tp {


// A bad --shadows / --shadow-budget combination (the budget cannot hold the lights).
struct ShadowError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ShadowLight {
    uint32_t light = 0;     // index in the scene's lights
    uint32_t firstFace = 0; // in ShadowPlan::faces
    uint32_t faceCount = 0; // 6 (cube) or 1 (spot)
    uint32_t edge = 0;      // texels per face edge
    double influence = 0.0; // screen pixels of its reach (the selection's key)
};

struct ShadowPlan {
    std::vector<ShadowLight> lights; // most influential first
    std::vector<gpu::ShadowFace> faces;
    uint32_t atlasWidth = 0, atlasHeight = 0; // the resident atlas (D32: 4 bytes a texel)
    uint32_t localWidth = 0, localHeight = 0; // one light's map, the largest light's block
    uint32_t requested = 0;                   // N, or the candidates for `all`
    bool empty() const { return lights.empty(); }
    uint64_t atlasBytes() const { return uint64_t(atlasWidth) * atlasHeight * 4; }
    uint64_t localBytes() const { return uint64_t(localWidth) * localHeight * 4; }
    uint64_t faceTexels() const; // what the faces cover (the atlas has no gaps but rounding)
    bool operator==(const ShadowPlan& o) const;
};

constexpr uint32_t kShadowMinEdge = 16;
constexpr uint32_t kShadowMaxEdge = 2048;
constexpr float kShadowNear = 1e-3f;          // 1 mm: nearer occluders are clipped
constexpr float kMaxSpotHalfAngle = 1.0472f;  // 60 degrees: a wider spot is shadowed as a cube

// `lights` and `frame` as uploaded (camera-relative); `width`/`height` the view.
ShadowPlan planShadows(const std::vector<gpu::LightGpu>& lights, const gpu::FrameUniforms& frame,
                       uint32_t width, uint32_t height, const ShadowSettings& settings,
                       uint32_t maxImageDimension);

// "none", "all", or N > 0 (a one-line ShadowError otherwise): --shadows.
ShadowSettings parseShadowCount(const std::string& text, ShadowSettings base = {});
std::string shadowCountText(const ShadowSettings& s);

} // namespace tp
