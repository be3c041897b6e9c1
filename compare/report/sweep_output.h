#pragma once
// What a sweep measured, run by run, and its three files: sweep.csv (one row per run, the
// headline figures), sweep.json (schema triptych.sweep/2: per run every pass's timings, the
// memory ledger, counters and every metric) and sweep.html (plots).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/measure/flip_measure.h"
#include "core/image/metrics.h"
#include "core/renderer/settings.h"
#include "core/runner/frame_runner.h"

namespace tp::cli {

struct SweepRow {
    std::string pipeline, status = "ok", error;
    int lights = 0;
    RenderSettings s;
    TimingStats frame;  // the whole frame; zero when failed
    uint64_t bytes = 0; // the pipeline's ledger total (scene data not included)
    double bytesPerPixel = 0, dropped = 0, seconds = 0;
    bool measured = false;                // error against the reference known
    ErrorReport hdr, display;             // against the reference: linear, and tonemapped
    FlipMeasure flip;                     // FLIP (tonemapped) and HDR-FLIP against the reference
    bool measuredCenter = false;          // under MSAA: error against the centre reference known
    ErrorReport hdrCenter, displayCenter; // against --reference-msaa center
    float exposureEv = 0, hdrPsnrPeak = 1;
    nlohmann::json run; // runJson(): every pass, the ledger, counters, left-out
    std::optional<FrameEfficiency> efficiency; // with a calibration (docs/efficiency.md)
    FrameEnergy energy;                        // the timed frames' (sweep.csv: joules_per_frame)
    std::string lightsHash;
    nlohmann::json referenceCache; // reference rows: where the run came from (reference_cache.h)
    size_t runIndex = 0;           // in the unsharded sweep's order (sweep.json: run_index)
    nlohmann::json path;           // --camera-path: seriesJson of its timing pass (path_run.h)
};

std::string sweepCsv(const std::vector<SweepRow>& rows, const std::string& device);
// The plots: every run that ran, one series per pipeline and value of each axis the sweep
// varied (MSAA, resolution, that pipeline's knobs); an empty plot says why it is empty.
std::string sweepHtml(const std::vector<SweepRow>& rows, const std::string& device,
                      const std::string& command);
// `header` carries the run-independent fields (schema, command, scene, device, axes);
// the runs are added under "runs".
nlohmann::json sweepJson(nlohmann::json header, const std::vector<SweepRow>& rows);

} // namespace tp::cli
