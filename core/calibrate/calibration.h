#pragma once
// The device's measured ceilings (`triptych calibrate`, docs/efficiency.md): microbenchmarks
// (compute dispatches and draws, core/calibrate/benches.h) whose work is counted exactly, each
// timed with GPU timestamps over repeats after one warm-up. A ceiling is a rate in billions of
// its unit per second (GB/s, GFLOP/s, Gfetch/s, Geval/s, Gpixel/s, Gtri/s, Gatomic/s): its
// median over the repeats and the slowest and fastest repeat.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tp {

class GpuContext;

struct Ceiling {
    std::string name; // e.g. "dram_read"
    std::string unit; // "GB/s", "GFLOP/s", "Geval/s", "Gpixel/s", ...
    std::string what; // one line: what was measured and how
    double median = 0, min = 0, max = 0; // the rate, in `unit`
    double medianMs = 0;                 // one dispatch's GPU time (median)
    double work = 0;                     // of one dispatch or draw, in the unit's base
    uint32_t repeats = 0;
};

struct CalibrationOptions {
    // Small working sets and short loops: a few seconds on lavapipe (the tests). The DRAM
    // figures are then not DRAM's (the buffers fit a large cache).
    bool quick = false;
    uint32_t repeats = 7; // timed dispatches per ceiling, after one warm-up
    std::function<void(const std::string&)> progress; // one line per ceiling; may be empty
};

// Every ceiling of this device, in a fixed order. Throws on a Vulkan failure.
std::vector<Ceiling> measureCeilings(GpuContext& ctx, const CalibrationOptions& options);

// The names measureCeilings returns, in its order (for tests and the JSON's readers).
std::vector<std::string> ceilingNames();

} // namespace tp
