#include "core/lightassign/bin_knob.h"

#include "core/gpu/context.h"

namespace tp::la {

Knob lightBinKnob() {
    return Knob::choice("light-bin", {"auto", "cpu", "gpu"},
                        "Where --light-cull binned builds each tile's candidates: cpu (once per configuration), "
                        "gpu (compute pass light_binning every frame: rectangles, counts, prefix sum, fill, sort; "
                        "the same runs) or auto (cpu on a CPU device such as lavapipe, else gpu)");
}

std::string resolveLightBin(const GpuContext& ctx, const std::string& value) {
    if (value == "cpu" || value == "gpu") return value;
    return ctx.isCpuDevice() ? "cpu" : "gpu";
}

} // namespace tp::la
