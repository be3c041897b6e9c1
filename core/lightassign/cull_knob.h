#pragma once
// The culling-strategy knob of the tiled pipelines, declared once here (like the tile size)
// so that Forward+ and deferred share one option.
#include "core/render/knobs.h"

namespace tp::la {

// --light-cull binned|all. binned (default): each tile tests only the lights whose
// conservative tile rectangle covers it (tile_candidates.h); all: every tile tests every
// light (brute force, tiles x lights), kept as the yardstick the binned lists must equal.
Knob lightCullKnob();

} // namespace tp::la
