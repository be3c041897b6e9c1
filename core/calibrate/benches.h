#pragma once
// The microbenchmarks of `triptych calibrate` as data: each one's shader kind, its dispatch or
// draw, and how much work one dispatch or draw does (docs/efficiency.md has the table). No
// device here: the list and its work counts are tested on the CPU.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "calibrate/calibrate_shared.h"
#include "core/gpu/pipelines.h"

namespace tp::calibrate {

// What a graphics benchmark draws, and into what.
struct BenchDraw {
    uint32_t vertex = TP_CAL_VERTEX_LAYERS;
    bool fragment = true;                     // false: depth only, no fragment shader
    VkFormat color = VK_FORMAT_UNDEFINED;     // none: no colour attachment
    std::vector<VkFormat> moreColors;         // attachments 1.. (the G-buffer ceilings)
    bool depth = false;                       // a D32 attachment, test GREATER and write
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    BlendMode blend = BlendMode::None;
    bool layered = false; // push.iterations are instances (layers), not loop steps
    bool cullAll = false; // every triangle culled (front and back): setup without raster
    uint32_t size = 0;    // the square target's edge in pixels
    // > 0: that many draws of one triangle from an indirect buffer, as few calls as the device's
    // multi-draw indirect allows (a call each without it), instead of `iterations` instances.
    uint32_t indirectDraws = 0;
};

struct Bench {
    const char* name;
    uint32_t kind; // TP_CAL_*: the compute or fragment shader's kind
    const char* unit;
    const char* what;
    bool graphics = false;
    BenchDraw draw;           // graphics only
    uint32_t invocations = 0; // compute: a multiple of TP_CAL_GROUP_SIZE
    gpu::CalPush push{};
    double work = 0; // of one dispatch or draw, in the unit's base (bytes, FLOPs, pixels, ...)
    // Loop-bound: the warm-up's time decides how many times longer the timed ones run.
    // Not the streams: they would read again what the same invocation just read, from a cache.
    bool scalable = true;

    bool indexed() const { return draw.vertex == TP_CAL_VERTEX_GRID_INDEXED; }
    // Vertices (non-indexed) or indices (indexed) of one instance.
    uint32_t vertexCount() const {
        return draw.vertex == TP_CAL_VERTEX_LAYERS ? 3u : push.stride * push.stride * 6u;
    }
    uint32_t instanceCount() const { return draw.layered ? push.iterations : 1u; }
};

// Every benchmark, in calibrate's order: `bufferBytes` for the streams (far larger than a last-
// level cache unless quick), short loops and small targets when quick.
std::vector<Bench> benches(uint64_t bufferBytes, bool quick);

// The square render target's edge of the graphics benchmarks.
uint32_t targetSize(bool quick);

// TP_CAL_VERTEX_GRID_INDEXED's index buffer: `cells` x `cells` cells of two triangles over
// (cells + 1)^2 shared vertices, row by row (the corners of TP_CAL_VERTEX_GRID, in its order).
std::vector<uint32_t> gridIndices(uint32_t cells);

} // namespace tp::calibrate
