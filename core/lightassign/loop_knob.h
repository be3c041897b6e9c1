#pragma once
// The light-loop knob of the clustered shading loop, declared once here (like the other
// light-assignment knobs) and read by the pipelines that walk cluster bitmasks.
#include <cstdint>
#include <string>

#include "core/render/knobs.h"

namespace tp {
struct DeviceCaps;
}

namespace tp::la {

// --light-loop lane|subgroup (docs/clustered.md). lane (default): every fragment walks its
// own cluster's bit row. subgroup: where every active lane of a subgroup shades the same
// tile, the lanes walk the OR of their rows together, each adding a light only where its
// own bit is set, so the light loads are uniform; other subgroups keep the lane loop. The
// same lights in the same order per fragment either way: identical images.
Knob lightLoopKnob();

// Whether the device runs the subgroup loop: vote (subgroupAllEqual), arithmetic
// (subgroupOr) and ballot (subgroupBroadcastFirst) in the fragment stage. Empty when it
// does; otherwise the reason, for the report's note.
std::string subgroupLoopUnsupported(const DeviceCaps& caps);

} // namespace tp::la
