#pragma once
// The tile-size knob of every pipeline that assigns lights to screen tiles. Declared here,
// once, so that Forward+ and deferred (and later clustered shading) share one option with
// one set of allowed values; the registry refuses two different declarations of a name.
#include "core/render/knobs.h"

namespace tp::la {

Knob tileSizeKnob();

} // namespace tp::la
