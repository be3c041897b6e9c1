#pragma once
// A run's energy in one line for a terminal or a panel: "0.412 J/frame (nvml: 83.1 W over
// 1003 ms, 240 frames)" or "energy unknown: REASON".
#include <string>

#include "core/energy/frame_energy.h"

namespace tp {

std::string energyLine(const FrameEnergy& e);

} // namespace tp
