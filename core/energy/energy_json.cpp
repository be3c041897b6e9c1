#include "core/energy/energy_json.h"

namespace tp {

nlohmann::json energyJson(const FrameEnergy& e) {
    nlohmann::json j;
    j["joules_per_frame"] = e.joulesPerFrame ? nlohmann::json(*e.joulesPerFrame) : nlohmann::json(nullptr);
    if (!e.joulesPerFrame) j["reason"] = e.reason;
    if (e.source.empty()) return j; // no meter read: the reason is all there is
    j["source"] = e.source;
    j["device"] = e.device;
    j["window_ms"] = e.windowMs;
    j["frames"] = e.frames;
    j["extended_frames"] = e.extendedFrames;
    j["min_window_ms"] = e.minWindowMs;
    j["joules"] = e.joules;
    j["watts"] = e.windowMs > 0 ? e.joules / (e.windowMs * 1e-3) : 0.0; // mean power over the window
    return j;
}

} // namespace tp
