#pragma once
// The light-assignment knobs of the tiled pipelines, declared once here (like the tile size)
// so that Forward+ and deferred share one option each (docs/clustered.md).
#include <cstdint>

#include "core/render/knobs.h"

namespace tp::la {

// --light-assign tiled|clustered. tiled (default): a light list per screen tile (Forward+:
// two when something is blended). clustered: tiles x depth slices; one list per tile over
// its whole depth span plus, per slice, a bitmask over that list.
Knob lightAssignKnob();

// --slices N: depth slices per tile of the clustered assignment (exponential in view
// distance over the tile's span). Changes nothing under --light-assign tiled.
Knob slicesKnob();

} // namespace tp::la
