#pragma once
// JSON records of a run (settings, device, timings, memory, statistics), shared by
// `render` (render.json) and the report writers.
#include <nlohmann/json.hpp>

#include "core/gpu/context.h"
#include "core/render/frame_runner.h"
#include "core/render/settings.h"
#include "core/scene/scene.h"

namespace tp::cli {

nlohmann::json deviceJson(const GpuContext& ctx);
nlohmann::json settingsJson(const RenderSettings& s);
nlohmann::json sceneJson(const Scene& scene, const SceneFeatures& f);
// Timings carry the device's name beside every figure set.
nlohmann::json runJson(const RunResult& run, const GpuContext& ctx);

} // namespace tp::cli
