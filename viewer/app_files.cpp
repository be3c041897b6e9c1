// What the viewer writes and reads: camera bookmarks (the camera file format every command
// reads with --camera) and exports.
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/camera/camera_file.h"
#include "core/camera/camera_path.h"
#include "core/reference/reference_renderer.h"
#include "viewer/viewer_app.h"

namespace tp::view {

void ViewerApp::saveBookmark(const std::string& path) {
    Status s = writeCameraFile(path, userCamera());
    error_ = s ? "" : s.error();
}

void ViewerApp::loadBookmark(const std::string& path) {
    Result<Camera> c = readCameraFile(path);
    if (!c) {
        // A list of bookmarks: the first.
        std::error_code ec;
        if (std::filesystem::is_regular_file(path, ec)) {
            try {
                std::ifstream in(path);
                nlohmann::json j = nlohmann::json::parse(in);
                if (j.is_array() && !j.empty()) c = cameraFromJson(j.front(), path + "[0]");
            } catch (const std::exception&) {
            }
        }
    }
    if (!c) {
        error_ = c.error();
        return;
    }
    setCamera(*c);
    error_.clear();
}

void ViewerApp::addPathKey() {
    pathKeys_.push_back(userCamera());
    error_.clear();
}

void ViewerApp::savePath(const std::string& path, uint32_t frames) {
    if (pathKeys_.empty()) {
        error_ = "no path keys yet: add the current camera as a key first";
        return;
    }
    const uint32_t n = frames ? frames : uint32_t(30 * (pathKeys_.size() - 1) + 1);
    Status s = writeCameraPath(path, pathKeys_, n, Interpolation::CatmullRom);
    error_ = s ? "" : s.error();
}

void ViewerApp::startExport(const std::string& dir) {
    // Before anything is written: a running export's compare still has to read camera.json.
    if (exporter_.busy()) {
        error_ = "an export is still running";
        return;
    }
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        error_ = "export: cannot create " + dir + " (" + ec.message() + ")";
        return;
    }
    const std::string camera = dir + "/camera.json";
    if (Status s = writeCameraFile(camera, userCamera()); !s) {
        error_ = s.error();
        return;
    }
    const float ev = state_.autoExposure ? autoEv_ : state_.exposureEv;
    std::vector<std::string> render = exportArguments(state_, "render", camera, ev);
    render.insert(render.begin(), options_.exe);
    render.insert(render.end(), {"--pipeline", state_.pipelineA, "--out", dir + "/render"});
    std::vector<std::string> compare = exportArguments(state_, "compare", camera, ev);
    compare.insert(compare.begin(), options_.exe);
    std::string
        pipelines; // A then B, without the reference (compare always renders it) or a repeat
    for (const std::string& p : {state_.pipelineA, state_.pipelineB})
        if (p != kReferenceRenderer && pipelines != p && pipelines.rfind(p + ",", 0) != 0)
            pipelines += (pipelines.empty() ? "" : ",") + p;
    if (pipelines.empty()) pipelines = cli::defaultPipelineList();
    compare.insert(compare.end(), {"--pipelines", pipelines, "--out", dir + "/compare"});
    if (!exporter_.start({render, compare}, dir + "/export.log"))
        error_ = "an export is still running";
}

} // namespace tp::view
