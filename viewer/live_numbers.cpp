#include "viewer/live_numbers.h"

#include <algorithm>

namespace tp::view {
namespace {

// The middle value, the middle two averaged (as every timing in the reports).
double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace

LiveRate liveRate(const TimingHistory& h) {
    LiveRate r;
    r.renders = h.wallMs.size();
    r.wallMs = median({h.wallMs.begin(), h.wallMs.end()});
    if (auto it = h.passes.find("frame"); it != h.passes.end())
        r.gpuMs = median({it->second.begin(), it->second.end()});
    return r;
}

uint64_t ledgerBytes(const std::vector<LedgerEntry>& entries) {
    uint64_t total = 0;
    for (const LedgerEntry& e : entries)
        total += e.bytes;
    return total;
}

LiveMemory liveMemory(const ViewerApp& app, const Shown& s) {
    LiveMemory m;
    if (s.run) m.pipeline = ledgerBytes(s.run->memory);
    m.scene = ledgerBytes(app.sceneMemory());
    return m;
}

} // namespace tp::view
