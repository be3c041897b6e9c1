#pragma once
// Export from the viewer runs this program's own `render` and `compare` commands on the
// current view (camera file, lights, knobs, resolution) in the background: the output is
// exactly what those commands write, made by their code, and the UI never waits on it.
#include <atomic>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "viewer/view_state.h"

namespace tp::view {

// The command line `triptych COMMAND` needs to reproduce `s` (camera from `cameraFile`).
std::vector<std::string> exportArguments(const ViewState& s, const std::string& command,
                                         const std::string& cameraFile, float exposureEv);

class Exporter {
  public:
    ~Exporter();
    // Runs the commands one after another on a background thread, output to `log`; refused
    // (false) while a previous export runs.
    bool start(std::vector<std::vector<std::string>> commands, std::string log);
    std::string status() const;
    bool busy() const { return busy_; }

  private:
    std::thread thread_;
    std::atomic<bool> busy_{false};
    mutable std::mutex mutex_;
    std::string status_;
};

} // namespace tp::view
