#pragma once
// An energy counter of the device that runs the frames, read before and after the timed frames
// (docs/efficiency.md, "Energy per frame"). Two sources: NVML's total-energy counter of an
// NVIDIA GPU (nvml_meter.h) and the CPU packages' RAPL counters through powercap, for a CPU
// device such as lavapipe (rapl_meter.h). Which one a device gets: open_energy.h. No Vulkan
// here: a source is tested on the CPU with a fake counter.
#include <memory>
#include <string>

#include "core/util/result.h"

namespace tp {

class EnergyMeter {
  public:
    virtual ~EnergyMeter() = default;
    virtual const char* source() const = 0;          // "nvml" or "rapl"
    virtual const std::string& device() const = 0;   // what the counter measures, in words
    // How often the counter moves, at worst: a reading can be this stale, so a window must be
    // many of these long (energy_window.h).
    virtual double updatePeriodMs() const = 0;
    // Joules since an origin of the meter's own, never decreasing between calls (a counter that
    // wrapped is unwrapped); error: one line saying what could not be read.
    virtual Result<double> joules() = 0;
};

// A meter, or why this device has none (one line: "no readable ...").
struct EnergySource {
    std::unique_ptr<EnergyMeter> meter;
    std::string why;
};

} // namespace tp
