#include "core/lightassign/cull_knob.h"

namespace tp::la {

Knob lightCullKnob() {
    return Knob::choice("light-cull", {"binned", "all"},
                        "Which lights a tile tests: binned (only those whose conservative tile rectangle covers it, "
                        "built as --light-bin says; cost lights + candidates) or all (every light: tiles x "
                        "lights); both keep exactly the same lists");
}

} // namespace tp::la
