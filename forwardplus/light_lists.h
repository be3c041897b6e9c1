#pragma once
// Forward+'s light-list memory, sized on the CPU when the renderer is planned: the index buffer
// of the chosen layout (fixed, compact, linked) and, with --light-assign clustered, the depth
// slices' bitmasks. Each refuses, with one line naming the knobs that shrink it, what
// maxStorageBufferRange cannot hold. The sizes are capacities: a later view (updateView) lays
// its lists out inside them, or the renderer is planned again (docs/forwardplus.md, "Many
// views").
#include <cstdint>
#include <string>
#include <vector>

#include "core/lightassign/tile_grid.h"

namespace tp {

class GpuContext;
namespace la {
struct LightClasses;
}

namespace fp {

struct ListConfig {
    uint32_t layout = 0;    // TP_FP_LAYOUT_*
    std::string layoutName; // --light-lists, for the error message
    uint64_t tiles = 0;
    uint32_t capacity = 0;   // fixed: --tile-capacity slots per tile and list
    uint64_t boundSlots = 0; // compact and linked: the conservative bound's slots (one list kind)
    uint32_t numLists = 1;   // 2 with a separate transparent list
};

struct ListSizes {
    uint64_t stride = 0;    // slots of one list kind (the transparent lists follow)
    uint64_t slots = 0;     // every list kind's
    uint64_t poolNodes = 0; // linked: nodes {light, next}, as many as slots (cannot overflow)
    uint64_t bytes = 0;     // the index buffer's, at least 16
    std::string purpose;    // the buffer's description in the frame graph
};

ListSizes sizeLists(const GpuContext& ctx, const ListConfig& c);

// Clustered: per tile, `slices` rows of ceil(bound / 32) words (a bit per slot of its list).
struct MaskLayout {
    std::vector<uint32_t> offsets; // tileCount + 1 word offsets (clamped to 32 bits)
    uint64_t words = 0;
};

// The layout of `bound`'s rows; sizeMasks also refuses words past maxStorageBufferRange.
MaskLayout layoutMasks(const std::vector<uint32_t>& bound, uint32_t slices);
MaskLayout sizeMasks(const GpuContext& ctx, const std::vector<uint32_t>& bound, uint32_t slices);

// fp_params: FpParams, then its words - the directional and local light indices, the
// per-tile offsets (compact layout or binned culling), the binned candidates (zeros that
// light_binning fills under --light-bin gpu) in room for `candidateSlots`, the clusters'
// mask-row offsets - uploaded when planned and again for every view (the same size: the
// candidates' room is a capacity); under --light-bin gpu only when planned (the frame writes
// the offsets, the candidates and the mask-row offsets of each view itself). Refuses, in one
// line, what maxStorageBufferRange cannot hold.
struct ParamsInput {
    la::TileGrid grid;
    const la::LightClasses* classes = nullptr;
    uint32_t layout = 0; // TP_FP_LAYOUT_*
    bool binned = false;
    const std::vector<uint32_t>* tileOffsets = nullptr;
    const std::vector<uint32_t>* candidates = nullptr; // CPU binning's; empty under gpu
    uint64_t candidateSlots = 0; // binned: the candidates' room (>= candidates->size())
    const std::vector<uint32_t>* maskOffsets = nullptr;
    uint32_t tileCapacity = 0;
    ListSizes lists;
};

struct PackedParams {
    std::vector<uint8_t> bytes;
    uint64_t candidateWord = 0; // the candidates' first word in the buffer
    uint64_t offsetWord = 0;    // the per-tile offsets' first word (the GPU binning writes them)
    uint64_t maskOffsetWord = 0; // clustered: the mask rows' offsets' first word (GPU binning too)
    std::string purpose;        // the buffer's description in the ledger
};

PackedParams packParams(const GpuContext& ctx, const ParamsInput& in);

} // namespace fp
} // namespace tp
