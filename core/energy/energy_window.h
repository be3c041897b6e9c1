#pragma once
// The energy of a run's timed frames: the meter read before the first timed frame and after the
// last, over the wall time between (docs/efficiency.md, "Energy per frame"). A counter that moves
// every P ms gives a reading up to P ms stale at each end, so a window of W ms is off by up to
// P/W of its energy; the window is held to at least kPeriodsPerWindow periods, by running the
// same frames on past the timed ones (extend) or, where a caller cannot wait (the viewer), by
// saying the window was too short.
#include <chrono>
#include <cstdint>

#include "core/energy/energy_meter.h"
#include "core/energy/frame_energy.h"

namespace tp {

// 10 periods: the energy per frame within about 10 % (an NVIDIA GPU's counter, ~100 ms at worst:
// a 1 s window).
constexpr double kPeriodsPerWindow = 10.0;
// Frames added to reach the window at most: a frame of microseconds would otherwise run a
// million times.
constexpr uint32_t kMaxExtendedFrames = 100000;

class EnergyWindow {
  public:
    // `meter` null: `why` is every result's reason (the source's one line).
    EnergyWindow(EnergyMeter* meter, std::string why);
    void begin(); // just before the first timed frame is submitted
    // After `extended` frames past the timed ones: whether the window is still too short to
    // measure, and another of the same frames should run.
    bool wantsMore(uint32_t extended) const;
    // Just after the last frame completed; `frames` ran in the window, `extended` of them added.
    FrameEnergy end(uint32_t frames, uint32_t extended);

  private:
    double minWindowMs() const;
    EnergyMeter* meter_;
    std::string why_;
    bool started_ = false;
    double startJoules_ = 0;
    double readMs_ = 0; // the first read's wall time
    std::chrono::steady_clock::time_point start_;
};

// The one-line reason of a window shorter than its counter allows.
std::string shortWindowReason(double windowMs, double minWindowMs, double periodMs);

} // namespace tp
