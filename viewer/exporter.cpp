#include "viewer/exporter.h"

#include <cstdio>
#include <cstdlib>
#include <sys/wait.h>

namespace tp::view {
namespace {

std::string quoted(const std::string& arg) {
    std::string out = "'";
    for (char c : arg)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

} // namespace

std::vector<std::string> exportArguments(const ViewState& s, const std::string& command,
                                         const std::string& cameraFile, float exposureEv) {
    const cli::SceneOptions& o = s.scene;
    std::vector<std::string> a = {command};
    if (!o.scene.empty()) a.push_back(o.scene);
    if (!o.lightsFile.empty()) a.insert(a.end(), {"--lights-file", o.lightsFile});
    a.insert(a.end(), {"--lights", std::to_string(o.lightCount), "--seed", std::to_string(o.seed),
                       "--light-types", o.lightTypes});
    if (!o.lightRadius.empty()) a.insert(a.end(), {"--light-radius", o.lightRadius});
    if (!o.lightIntensity.empty()) a.insert(a.end(), {"--light-intensity", o.lightIntensity});
    if (o.dropSceneLights) a.push_back("--no-scene-lights");
    if (o.strict) a.push_back("--strict");
    a.insert(a.end(), {"--res", std::to_string(s.width) + "x" + std::to_string(s.height), "--msaa",
                       std::to_string(s.msaa)});
    for (const auto& [name, value] : s.knobs)
        a.insert(a.end(), {"--" + name, value});
    char ev[32];
    std::snprintf(ev, sizeof(ev), "%.6g", exposureEv);
    a.insert(a.end(), {"--exposure", ev});
    if (!cameraFile.empty()) a.insert(a.end(), {"--camera", cameraFile});
    return a;
}

Exporter::~Exporter() {
    if (thread_.joinable()) thread_.join();
}

bool Exporter::start(std::vector<std::vector<std::string>> commands, std::string log) {
    if (busy_) return false;
    if (thread_.joinable()) thread_.join();
    busy_ = true;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        status_ = "exporting (log: " + log + ")...";
    }
    thread_ = std::thread([this, commands = std::move(commands), log] {
        std::string result = "export done: see " + log;
        for (const std::vector<std::string>& argv : commands) {
            std::string line;
            for (const std::string& a : argv)
                line += quoted(a) + " ";
            line += ">> " + quoted(log) + " 2>&1";
            int rc = std::system(line.c_str());
            if (rc != 0) {
                int code = WIFEXITED(rc) ? WEXITSTATUS(rc) : rc;
                result = "export failed (exit " + std::to_string(code) + "): see " + log;
                break;
            }
        }
        std::lock_guard<std::mutex> lock(mutex_);
        status_ = result;
        busy_ = false;
    });
    return true;
}

std::string Exporter::status() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return status_;
}

} // namespace tp::view
