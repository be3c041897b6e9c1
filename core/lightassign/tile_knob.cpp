#include "core/lightassign/tile_knob.h"

namespace tp::la {

Knob tileSizeKnob() {
    Knob k;
    k.name = "tile";
    k.kind = Knob::Kind::Integer;
    // 8 to 32: one workgroup per tile within lavapipe's and every desktop GPU's limits.
    k.values = {"8", "16", "32"};
    k.defaultValue = "16";
    k.help = "Tile edge in pixels of the tiled light assignment";
    return k;
}

} // namespace tp::la
