#include "core/energy/energy_window.h"

#include <cstdio>

#include "core/util/clock.h"

namespace tp {

EnergyWindow::EnergyWindow(EnergyMeter* meter, std::string why) : meter_(meter), why_(std::move(why)) {}

double EnergyWindow::minWindowMs() const {
    return meter_ ? kPeriodsPerWindow * meter_->updatePeriodMs() : 0.0;
}

void EnergyWindow::begin() {
    if (!meter_) return;
    const auto reading = std::chrono::steady_clock::now();
    Result<double> j = meter_->joules();
    readMs_ = msSince(reading);
    if (!j) {
        why_ = j.error();
        return;
    }
    startJoules_ = *j;
    start_ = std::chrono::steady_clock::now();
    started_ = true;
}

bool EnergyWindow::wantsMore(uint32_t extended) const {
    return started_ && extended < kMaxExtendedFrames && msSince(start_) < minWindowMs();
}

std::string shortWindowReason(double windowMs, double minWindowMs, double periodMs) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "window %.1f ms shorter than the %.0f ms its counter needs (it moves about every "
                  "%.0f ms)",
                  windowMs, minWindowMs, periodMs);
    return text;
}

FrameEnergy EnergyWindow::end(uint32_t frames, uint32_t extended) {
    FrameEnergy e;
    e.frames = frames;
    e.extendedFrames = extended;
    if (!meter_ || !started_) {
        e.reason = why_;
        return e;
    }
    e.windowMs = msSince(start_);
    e.source = meter_->source();
    e.device = meter_->device();
    e.minWindowMs = minWindowMs();
    const auto reading = std::chrono::steady_clock::now();
    Result<double> j = meter_->joules();
    e.readMs = readMs_ + msSince(reading);
    if (!j) {
        e.reason = j.error();
        return e;
    }
    e.joules = *j - startJoules_;
    if (frames == 0) e.reason = "no frame was timed";
    else if (e.windowMs < e.minWindowMs)
        e.reason = shortWindowReason(e.windowMs, e.minWindowMs, meter_->updatePeriodMs());
    else if (e.joules <= 0.0) {
        char text[120];
        std::snprintf(text, sizeof text, "the %s counter did not move in %.0f ms", e.source.c_str(),
                      e.windowMs);
        e.reason = text;
    } else e.joulesPerFrame = e.joules / double(frames);
    return e;
}

} // namespace tp
