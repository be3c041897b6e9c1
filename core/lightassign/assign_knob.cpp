#include "core/lightassign/assign_knob.h"

namespace tp::la {

Knob lightAssignKnob() {
    return Knob::choice("light-assign", {"tiled", "clustered"},
                        "Light assignment: tiled (a list per screen tile and depth range) or clustered (tiles x "
                        "depth slices: a list per tile over its depth span, a bitmask over it per slice)");
}

Knob slicesKnob() {
    // Up to 64: a slice's bitmask costs one bit per light of the tile list.
    return Knob::integerOf("slices", {"4", "8", "16", "32", "64"}, "16",
                           "Depth slices per tile of --light-assign clustered (exponential in view distance)");
}

} // namespace tp::la
