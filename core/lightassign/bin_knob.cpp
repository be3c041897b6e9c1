#include "core/lightassign/bin_knob.h"

#include "core/gpu/context.h"

namespace tp::la {

Knob lightBinKnob() {
    return Knob::choice("light-bin", {"auto", "cpu", "gpu"},
                        "Where --light-cull binned builds each tile's candidates: cpu (once per configuration), "
                        "gpu (every frame, timed passes light_binning: rectangles, counts, prefix sum; light_bin_fill; "
                        "light_bin_sort: each run ascending; the same runs as cpu) or auto (cpu on a CPU device "
                        "such as lavapipe, where the sort costs more than the CPU's scatter; else gpu)");
}

std::string resolveLightBin(const GpuContext& ctx, const std::string& value) {
    if (value == "cpu" || value == "gpu") return value;
    return ctx.isCpuDevice() ? "cpu" : "gpu";
}

} // namespace tp::la
