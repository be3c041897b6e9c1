#pragma once
// Each pass placed against the device's measured ceilings (docs/efficiency.md): from its
// counted work (pass_work.h) the time it would take at each ceiling its work meets; the largest
// is its binding ceiling, and that time over the measured one is how close the pass came.
// No device here: tested on the CPU.
#include <map>
#include <string>
#include <vector>

#include "core/calibrate/pass_work.h"
#include "core/gpu/profiler.h"

namespace tp {

// Ceiling medians by name (calibrate's names), in the base unit per second: bytes/s, FLOP/s,
// evaluations/s, pixels/s, triangles/s.
using CeilingRates = std::map<std::string, double>;

struct LimitTime {
    std::string limit;   // "memory", "light_alu", "raster", "triangles", "texture", "atomics"
    std::string ceiling; // the calibrate ceiling(s) it divides by
    double ms = 0;       // the pass's counted work at that ceiling
};

struct PassEfficiency {
    std::string pass;
    double measuredMs = 0;
    std::vector<LimitTime> limits; // every limit the pass's counted work meets
    LimitTime bound;               // the largest of them: the binding ceiling
    double percent = 0;            // bound.ms / measuredMs x 100 (0: no counted work)
    // The roofline: light evaluations as the FLOPs of the FMA loop that takes the same time on
    // the same stage, against the bytes moved. 0 without light evaluations.
    double flops = 0, bytes = 0;
    std::string roof; // "fp32_fma" (compute) or "fragment_fma": the pass's ALU roof
};

struct FrameEfficiency {
    double frameMs = 0;
    double boundSumMs = 0; // every pass at its binding ceiling
    double percent = 0;    // boundSumMs / frameMs x 100
    std::vector<PassEfficiency> passes;
    std::vector<std::string> missingCeilings; // needed and absent from the calibration
    // The pass's placement when its counted work met a ceiling; null otherwise.
    const PassEfficiency* placed(const std::string& pass) const {
        for (const PassEfficiency& p : passes)
            if (p.pass == pass && !p.limits.empty()) return &p;
        return nullptr;
    }
};

// `spotShare`: the share of the scene's local lights that are spots (their evaluations are
// placed against the spot ceilings). Timings: the run's ("frame" first, then the passes).
FrameEfficiency placeFrame(const std::vector<PassWork>& work, const std::vector<TimingStats>& timings,
                           const CeilingRates& rates, double spotShare);

} // namespace tp
