#include "core/energy/energy_text.h"

#include <cstdio>

namespace tp {

std::string energyLine(const FrameEnergy& e) {
    if (!e.joulesPerFrame) return "energy unknown: " + e.reason;
    char text[160];
    std::snprintf(text, sizeof text, "%.4g J/frame (%s: %.1f W over %.0f ms, %u frames%s)", *e.joulesPerFrame,
                  e.source.c_str(), e.windowMs > 0 ? e.joules / (e.windowMs * 1e-3) : 0.0, e.windowMs,
                  e.frames, e.extendedFrames > 0 ? ", window extended" : "");
    return text;
}

} // namespace tp
