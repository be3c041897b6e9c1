#pragma once
// A camera path (issue: the camera moves): every pipeline and the reference planned once
// (RendererSession, RenderSettings::manyViews) and rendered at every view of the path, the
// lights moved per view where --light-motion says so. Two passes, so that nothing on the CPU
// sits between the frames being timed:
//   1. timing: per pipeline, the views back to back (after one warm-up), each its own view
//      update, then --frames timed frames; no readback;
//   2. images: per view, the reference (reused where neither the camera nor the lights moved),
//      each pipeline's frame read back and measured against it.
// compare then writes its full report at the path's worst view (the largest error of any
// pipeline), with the path's series, percentiles and ranking flips in report.json ("path")
// and report.html (docs/camera_paths.md).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/image/metrics.h"
#include "core/runner/frame_runner.h"
#include "core/scene/scene.h"

namespace tp::cli {

struct PathInput {
    std::string source;        // the path file, for the report
    std::vector<Camera> views; // at least one
    // The lights of view v (same count, same types as the scene's); null: they do not move.
    std::function<std::vector<Light>(uint32_t view)> lightsAt;
    std::string lightMotion = "none"; // as given, for the report
};

struct PathSeries {
    std::string name;
    std::string error;                     // failed: why (its series end where it failed)
    std::vector<double> frameMs, updateMs; // per view: median GPU frame, CPU view update
    std::vector<ErrorReport> hdr;          // per view, against the view's reference (pipelines)
    std::vector<double> displayPsnr;       // per view, tonemapped at the path's one exposure
    uint32_t updates = 0, replans = 0;     // how it followed views 1.. of the timing pass
};

struct PathRecord {
    PathInput input;
    std::vector<PathSeries> pipelines;
    uint32_t referenceRenders = 0, referenceReused = 0;
    double referenceMs = 0; // wall time of the reference renders (not timed per pass)
    uint32_t worstView = 0; // the largest hdr rmse of any pipeline
    float exposureEv = 0;   // of the display PSNR: from the first view's reference
    // Views where the order of the pipelines by frame time changed from the previous view: a
    // pipeline overtook another by more than kRankMargin of the slower one's time.
    struct Flip {
        uint32_t view = 0;
        std::vector<std::string> before, after; // fastest first
    };
    std::vector<Flip> rankFlips;
};

inline constexpr double kRankMargin = 0.05;

struct PathRunSetup {
    GpuContext& ctx;
    Scene& scene; // its camera and lights are set per view (left at the last view)
    SceneGpu& gpuScene;
    SceneFeatures features;
    RenderSettings settings;
    std::vector<std::string> pipelines; // without the reference
    int warmup = 1, frames = 3;
    std::string exposure = "auto";
};

PathRecord runPath(const PathRunSetup& setup, const PathInput& input);
// The timing pass alone, for one pipeline (render --camera-path): no reference, no images.
PathSeries timePath(const PathRunSetup& setup, const PathInput& input, const std::string& pipeline);
// Sets the scene (camera and lights) to view v of the path.
void applyPathView(Scene& scene, SceneGpu& gpuScene, const PathInput& input, uint32_t v);

nlohmann::json pathJson(const PathRecord& path);
// One pipeline's series and its percentiles (an element of pathJson's "pipelines").
nlohmann::json seriesJson(const PathSeries& series);
// Of the finite `values`: the median (the middle two averaged, as every timing here), the
// 95th and 99th percentiles (nearest rank) and the maximum; null when none is finite.
nlohmann::json percentilesJson(std::vector<double> values);

} // namespace tp::cli
