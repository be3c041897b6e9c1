#pragma once
// JSON records of a run (settings, device, timings, memory, statistics), shared by
// `render` (render.json) and the report writers.
#include <nlohmann/json.hpp>

#include "core/cli/cli_common.h"
#include "core/energy/energy_meter.h"
#include "core/gpu/context.h"
#include "core/image/metrics.h"
#include "core/renderer/settings.h"
#include "core/runner/frame_runner.h"
#include "core/scene/scene.h"

namespace tp::cli {

nlohmann::json deviceJson(const GpuContext& ctx);
nlohmann::json settingsJson(const RenderSettings& s);
nlohmann::json sceneJson(const Scene& scene, const SceneFeatures& f);
// Where a run's camera came from: {kind, gltf_camera | path, description}. The camera itself
// is written by cameraToJson (core/camera/camera_file.h), so that object is a camera file.
nlohmann::json cameraSourceJson(const CameraSource& source);
// Timings carry the device's name beside every figure set.
// Memory: {resources, total_bytes, bytes_per_pixel} (per output pixel).
// With "energy" (the timed frames' joules per frame or why not, core/energy/energy_json.h) and
// "pass_statistics" ({collected, reason}); without the statistics "work" is null.
nlohmann::json runJson(const RunResult& run, const GpuContext& ctx);
// The command's energy counter: {available, source, device, update_period_ms, min_window_ms}, or
// {available: false, reason}.
nlohmann::json energySourceJson(const EnergySource& source);
// "triptych: energy left out: WHY" on stderr when the device has no counter (once per command).
void noteEnergyLeftOut(const EnergySource& source);
// Ledger entries as {resources: [...], total_bytes}; total is the sum of the entries' bytes.
nlohmann::json ledgerJson(const std::vector<LedgerEntry>& entries);
// Every metric of metricTable() by name, plus the location of the largest difference and
// the pixel count compared. A PSNR of +inf (identical images) is written as null.
nlohmann::json metricsJson(const ErrorReport& e);

} // namespace tp::cli
