#include "core/lightassign/tile_knob.h"

namespace tp::la {

Knob tileSizeKnob() {
    // 8 to 32: one workgroup per tile within lavapipe's and every desktop GPU's limits.
    return Knob::integerOf("tile", {"8", "16", "32"}, "16", "Tile edge in pixels of the tiled light assignment");
}

} // namespace tp::la
