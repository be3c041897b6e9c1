#pragma once
// The counted work of every pass and its place against the device's ceilings, as JSON
// (render.json and report.json "run.work" and "run.efficiency"; docs/efficiency.md).
#include <nlohmann/json.hpp>

#include "core/calibrate/efficiency.h"
#include "core/calibrate/pass_work.h"

namespace tp::cli {

nlohmann::json passWorkJson(const std::vector<PassWork>& work);
nlohmann::json efficiencyJson(const FrameEfficiency& f);

} // namespace tp::cli
