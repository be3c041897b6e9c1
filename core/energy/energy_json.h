#pragma once
// The report's "energy" object of a run (docs/report.md), shared by report.json, render.json,
// sweep.json and the viewer's stats: {joules_per_frame, watts, joules, window_ms, frames,
// extended_frames, min_window_ms, source, device}, or {joules_per_frame: null, reason} with
// whatever was measured before the reason arose.
#include <nlohmann/json.hpp>

#include "core/energy/frame_energy.h"

namespace tp {

nlohmann::json energyJson(const FrameEnergy& e);

} // namespace tp
