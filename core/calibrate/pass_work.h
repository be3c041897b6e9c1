#pragma once
// Each pass's work, counted (docs/efficiency.md, "Placing a pass: what is counted"): the bytes its declared
// uses move, what the device counted it doing (pipeline statistics) and the light evaluations
// its renderer counts. No device here: tested on the CPU against hand-computed passes.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/gpu/graph_plan.h"
#include "core/gpu/pass_statistics.h"
#include "core/renderer/renderer.h"

namespace tp {

// Which ALU a pass's shading runs on, and which raster path its fragments take: what decides
// the ceilings it is placed against. Msaa: colour at more than one sample (with or without
// depth); DepthOnlyMsaa: depth alone at more than one sample; GBuffer(Msaa): three colour
// attachments or more (kGBufferTargets), at one sample (more).
enum class PassStage { Compute, Graphics, Other };
enum class RasterPath { None, DepthOnly, Colour, Msaa, DepthOnlyMsaa, GBuffer, GBufferMsaa };
// The colour attachments calibrate's G-buffer ceilings write (rop_gbuffer): a pass with fewer
// does less per pixel and is placed against the one-target ceilings.
constexpr uint32_t kGBufferTargets = 3;

// One kind of a pass's other counted work (PassOpWork), summed over the renderer's entries.
struct CountedOps {
    PassOpWork::Kind kind;
    double count = 0;
    bool exact = true; // every entry exact
    std::string how;   // the entries' lines, joined by "; "
};

struct PassWork {
    std::string pass;
    PassStage stage = PassStage::Other;
    RasterPath raster = RasterPath::None;
    double bytesRead = 0, bytesWritten = 0; // the frame graph's declared uses, each once
    double imageBytesRead = 0;              // the part of bytesRead read from images
    double msaaImageBytesRead = 0;          // the part of imageBytesRead read from multisampled images
    bool counted = false;                   // pipeline statistics were available
    PipelineCounts counts;
    double rasterPixels = 0; // placed against the raster ceilings
    double lightEvaluations = 0;
    bool lightExact = false;
    std::string lightHow; // empty: the pass evaluates no light
    std::vector<CountedOps> ops; // texture fetches, atomics, light-vs-tile tests: those counted
    double opCount(PassOpWork::Kind kind) const {
        for (const CountedOps& o : ops)
            if (o.kind == kind) return o.count;
        return 0;
    }
};

// What one use moves of a resource of `bytes`: attachments are written (a depth attachment is
// also read by its test; blending's read of a colour attachment is not counted), storage
// writes are written, the others read. countPassWork bounds a counted draw's attachment bytes
// by its fragments (each writes at most one pixel's samples): a pass that draws a few blended
// surfaces does not move the whole target.
struct UseBytes {
    double read = 0, written = 0;
};
UseBytes useBytes(Use use, double bytes);

struct PassWorkInput {
    const GraphDecl* decl = nullptr;
    std::vector<uint32_t> livePasses;                 // declaration indices, in recording order
    std::function<uint64_t(uint32_t)> resourceBytes; // FrameGraph::contentBytes
    std::function<uint32_t(uint32_t)> resourceSamples;
    std::vector<PassCounts> counts;     // empty without pipeline statistics
    std::vector<PassLightWork> lightWork;
    std::vector<PassOpWork> opWork;
    double coveredPixels = 0; // pixels whose depth is not the far plane
    double framePixels = 0;   // width x height: an attachment's bytes per pixel, from its size
};

std::vector<PassWork> countPassWork(const PassWorkInput& in);

} // namespace tp
