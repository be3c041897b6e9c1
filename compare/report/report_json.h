#pragma once
// The compare run as data (what was rendered, how it went, how it measures up) and its
// report.json (schema "triptych.report/2", documented in docs/report.md).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/cache/calibration_cache.h"
#include "compare/measure/flip_measure.h"
#include "compare/cache/reference_cache.h"
#include "compare/cache/scene_hash.h"
#include "core/energy/energy_meter.h"
#include "core/gpu/context.h"
#include "core/gpuscene/shadow_plan.h"
#include "core/image/difference.h"
#include "core/image/metrics.h"
#include "core/runner/frame_runner.h"
#include "core/scene/scene.h"

namespace tp::cli {

struct PipelineOutcome {
    std::string name;
    std::string error;              // why it failed; empty when it ran
    std::optional<RunResult> run;   // set when it ran
    ErrorReport hdr;                // against the reference, linear
    ErrorReport display;            // against the reference, tonemapped (same exposure)
    float diffP99 = 0;              // 99th percentile of max-channel |diff| (linear)
    FlipMeasure flip;               // FLIP and HDR-FLIP against the reference
    std::vector<std::string> files; // written into --out, relative names
    // Under MSAA, against the reference shaded at the pixel centre (--reference-msaa center).
    std::optional<ErrorReport> hdrVsCenter, displayVsCenter;
    // With --shadows, against the reference that samples the pipelines' shadow maps
    // (--reference-shadows maps) instead of casting rays: the lighting architecture's error alone.
    std::optional<ErrorReport> hdrVsShadowMaps, displayVsShadowMaps;
    ReferenceCacheUse cache; // the reference runs: whether the cache gave or took the run
};

struct PairOutcome {
    std::string a, b; // b is the "reference" side of computeError
    ErrorReport hdr, display;
    float diffP99 = 0;              // of |a - b|, on the report's shared scale
    std::vector<std::string> files; // a_vs_b_diff.exr / .png
};

// What the user asked for, as report.json records it: enough to repeat the run.
struct CompareRequest {
    std::vector<std::string> commandLine;
    uint64_t seed = 1;
    std::string scenePath; // as given; empty: the built-in scene
    std::string lightTypes;
    int lightsRequested = 0;
    int frames = 0, warmup = 0;
    std::string exposure;       // "auto" or an EV, as given
    float flipDistance = 0.7f;  // FLIP's viewing distance, metres
    bool centerReference = true; // false: --no-center-reference
};

struct CompareRecord {
    CompareRequest request;
    const Scene* scene = nullptr;
    SceneFeatures features;
    RenderSettings settings;
    const GpuContext* ctx = nullptr;
    std::string sceneHash;     // FNV-1a 64 of the scene file, hex; empty for built-ins
    FileHashes sceneFiles;     // the file and every file it references; empty for built-ins
    std::string contentHash;   // the loaded geometry, materials, textures, camera (any scene)
    std::string lightsHash;    // the lights rendered (file lights and generated ones)
    CameraSource cameraSource; // where scene->camera came from (--camera, glTF, built-in)
    float exposureEv = 0;
    float diffScale = 0;                   // shared heat-map scale
    float hdrPsnrPeak = 1;                 // brightest finite reference channel
    std::vector<LedgerEntry> sharedMemory; // owner "scene": counted once
    PipelineOutcome reference;
    // Under MSAA (unless --no-center-reference): the reference with --reference-msaa center;
    // its hdr/display are its own distance from the supersampled reference. No run: not rendered.
    PipelineOutcome centerReference;
    // With --shadows (unless the reference itself used the maps): the reference again with
    // --reference-shadows maps.
    PipelineOutcome shadowMapReference;
    ShadowPlan shadowPlan; // the lights the run shadowed and their maps (SceneGpu's, at its view)
    std::vector<PipelineOutcome> pipelines;
    std::vector<PairOutcome> pairs;
    std::vector<std::string> validationMessages;
    std::shared_ptr<const RunCalibration> calibration; // the ceilings passes are placed against
    std::shared_ptr<EnergySource> energy; // the device's energy counter (every run reads it)
    nlohmann::json path; // with --camera-path or --light-motion: pathJson (compare/measure/path_run.h)
};

nlohmann::json reportJson(const CompareRecord& r);

// argv as one string a POSIX shell splits back into the same words.
std::string shellJoin(const std::vector<std::string>& args);
// FNV-1a 64 of a file's bytes as 16 hex digits; empty when it cannot be read.
std::string hashFile(const std::string& path);

} // namespace tp::cli
