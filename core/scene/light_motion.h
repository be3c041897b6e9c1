#pragma once
// Moving lights (--light-motion MODE[:SPEED], docs/camera_paths.md): seeded motions that give
// each frame of a path its light positions, so a run measures dynamic lights reproducibly.
//
// Frame k's lights are a function of (start lights, motion, scene bounds, k) alone: nothing is
// carried from frame to frame, so any view of a path can be rendered by itself and shards of
// one run agree. Lights keep their count, order, type, colour, intensity, range, direction
// and cones; only point and spot lights' positions change, and frame 0 is the start.
//   orbit  each light runs round a horizontal circle through its start position (a vertical
//          axis beside it at a seeded radius, a seeded side and sense), `speed` scene units of
//          arc per frame; the circle is shrunk to stay inside the bounds when the light starts
//          inside them.
//   drift  each light wanders smoothly about its start position, per axis a sum of three sines
//          with seeded phases and amplitudes, never further per frame than `speed` scene units
//          and never out of the bounds it starts inside (an axis along which it starts outside
//          the bounds holds still).
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp {

struct LightMotion {
    enum class Mode { None, Orbit, Drift };
    Mode mode = Mode::None;
    // Scene units (metres) per frame: orbit's arc per frame, drift's largest step in a frame.
    float speed = 0.0f;
    uint64_t seed = 1;
};

// When MODE has no :SPEED: 5 cm a frame crosses the 60 m courtyard's bays (4 m) in 80 frames,
// so a 120-view path sees lights move without leaving their neighbourhood.
inline constexpr float kDefaultLightSpeed = 0.05f;
// Faster than this a light jumps across any scene in a frame: surely a typo.
inline constexpr float kMaxLightSpeed = 1e6f;

// "none", "orbit", "drift", optionally ":SPEED" (a number > 0, scene units per frame; not with
// "none"). The seed is the caller's (the run's light seed). Errors are one line that quote the
// text.
Result<LightMotion> parseLightMotion(const std::string& text);
// "none", "orbit:0.05" ...: what parseLightMotion reads back as `motion` (seed aside).
std::string lightMotionToString(const LightMotion& motion);

// The lights of frame `frame` (see the header comment). `sceneBounds` should be the scene's
// bounds (Scene::bounds), the same for every frame. Works out every light's motion again: for
// many frames keep a LightMotionPlan (the same lights, bit for bit).
std::vector<Light> moveLights(const std::vector<Light>& start, const LightMotion& motion,
                              const Aabb& sceneBounds, uint32_t frame);

// Each light's seeded circle or sines, worked out once, so that a frame costs a few sines per
// light (docs/camera_paths.md has the cost at 1,024 lights): what a run keeps for a path.
class LightMotionPlan {
  public:
    LightMotionPlan(const std::vector<Light>& start, const LightMotion& motion,
                    const Aabb& sceneBounds);
    std::vector<Light> at(uint32_t frame) const;

    // One light's motion: an offset from its start, zero at frame 0.
    struct Path {
        bool moves = false;
        double radius = 0.0, phase = 0.0, cosPhase = 0.0, sinPhase = 0.0; // orbit
        double rate = 0.0; // orbit: radians per frame
        struct Term {
            double amplitude = 0.0, rate = 0.0, phase = 0.0, sinPhase = 0.0; // rate: per frame
        };
        Term drift[3][3]; // [axis][term]; an axis that holds still has zero amplitudes
    };

  private:
    std::vector<Light> start_;
    std::vector<Path> paths_;
    LightMotion motion_;
    Aabb bounds_;
};

} // namespace tp
