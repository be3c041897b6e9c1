#pragma once
// Per pipeline, what a user of an interactive tool watches: frames per second and GPU memory,
// live (the numbers panel and the script's `stats` show the same values).
#include <cstdint>
#include <vector>

#include "core/gpu/ledger.h"
#include "viewer/viewer_app.h"

namespace tp::view {

struct LiveRate {
    size_t renders = 0; // how many renders the medians are over (at most TimingHistory::kHistory)
    double wallMs = 0;  // median wall time of a render: what a new view costs in this viewer
    double gpuMs = 0;   // median GPU frame
    double shownFps() const { return wallMs > 0 ? 1000.0 / wallMs : 0.0; }
    double gpuFps() const { return gpuMs > 0 ? 1000.0 / gpuMs : 0.0; }
};

// Over the last renders of one pipeline (its wall times and GPU frame times).
LiveRate liveRate(const TimingHistory& h);

struct LiveMemory {
    uint64_t pipeline = 0, scene = 0; // its memory ledger's bytes; the shared scene upload's
    uint64_t total() const { return pipeline + scene; }
};

uint64_t ledgerBytes(const std::vector<LedgerEntry>& entries);
// Of the shown image `s`; the scene is what the pipelines' worker uploaded (every pipeline
// reads that one upload).
LiveMemory liveMemory(const ViewerApp& app, const Shown& s);

} // namespace tp::view
