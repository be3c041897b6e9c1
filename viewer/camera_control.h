#pragma once
// Fly and orbit moves of the scene camera (position, target, up), in scene units and
// degrees. Fly turns the view around the eye; orbit turns the eye around the target.
#include "core/scene/scene.h"

namespace tp::view {

// forward/right/up: distances along the view's axes; the target moves with the eye.
void flyMove(Camera& c, float forward, float right, float up);
// Turns the view direction around the eye (yaw about `up`, pitch about the right axis).
void flyTurn(Camera& c, float yawDegrees, float pitchDegrees);
// Turns the eye around the target at a constant distance.
void orbit(Camera& c, float yawDegrees, float pitchDegrees);
// Moves the eye towards the target by `factor` of the distance (0.1: 10% closer).
void dolly(Camera& c, float factor);
// A step size that suits the scene: the eye-to-target distance / 20 (never 0).
float moveStep(const Camera& c);

} // namespace tp::view
