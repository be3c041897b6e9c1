#pragma once
// What a run's timed frames cost in energy: the report's "energy" object (docs/report.md).
#include <cstdint>
#include <optional>
#include <string>

namespace tp {

struct FrameEnergy {
    std::optional<double> joulesPerFrame; // none: `reason` says why
    std::string reason;
    std::string source, device; // the meter's (EnergyMeter::source, device)
    double joules = 0;          // over the window
    double windowMs = 0;        // wall time from before the first frame to after the last
    uint32_t frames = 0;        // frames in the window: the timed ones and any added (extended)
    uint32_t extendedFrames = 0; // added past the timed frames to reach minWindowMs
    double minWindowMs = 0;     // the window the counter's update period asks for
    double readMs = 0;          // wall time spent reading the counter (its two reads)
};

} // namespace tp
