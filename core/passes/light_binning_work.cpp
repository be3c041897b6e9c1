// The GPU binning's counted work (core/passes/light_binning.h): its counters, and per pass the
// bytes and atomics the efficiency placement reads (docs/efficiency.md).
#include <algorithm>
#include <cstring>

#include "core/lightassign/corner_atomics.h"
#include "core/passes/light_binning.h"
#include "core/renderer/renderer.h"
#include "include/light_binning.h"

namespace tp::la {

// The frame's rectangles (read back) to bin_rects.comp's atomics.
uint64_t GpuBinning::countCornerAtomics(const std::vector<uint8_t>& rectBytes) const {
    std::vector<TileRect> rects(std::min<size_t>(locals_, rectBytes.size() / 8));
    for (size_t k = 0; k < rects.size(); ++k) {
        glm::uvec2 packed;
        std::memcpy(&packed, rectBytes.data() + k * 8, 8);
        const glm::ivec4 r = gpu::binUnpackRect(packed); // x0, x1, y0, y1
        rects[k] = {r.x, r.y, r.z, r.w};
    }
    return binCornerAtomics(rects, grid_);
}

void GpuBinning::addStats(RendererStats& s, uint64_t slots) const {
    s.counters.push_back({"light_bin_sizing_runs", double(sizingRuns_)});
    s.counters.push_back({"light_bin_sort_fallbacks", double(sortFallbacks_)});
    addBinningWork(s, slots, locals_, cornerAtomics_);
}

void addBinningWork(RendererStats& s, uint64_t slots, uint32_t locals, uint64_t corners) {
    using Kind = PassOpWork::Kind;
    using Base = PassLightWork::Base;
    const double pairs = double(slots), lights = double(locals);
    // binRect reads a light's index and its position and range (bin_common.glsl), 20 bytes.
    s.opWork.push_back({"light_binning", Kind::BytesRead, Base::Items, 20.0, false,
                        "each light's index, position and range, once (at least)", lights});
    s.opWork.push_back({"light_binning", Kind::GlobalAtomics, Base::Items, 1.0, true,
                        "one to four atomicAdds per light that covers a tile: its rectangle's "
                        "corners in the difference array, or one per tile of a rectangle with "
                        "fewer tiles than corners (the direct counts)",
                        double(corners)});
    s.opWork.push_back({"light_bin_fill", Kind::GlobalAtomics, Base::Items, 1.0, true,
                        "one atomicAdd per (light, tile) pair: its slot in the tile's run", pairs});
    s.opWork.push_back({"light_bin_fill", Kind::BytesWritten, Base::Items, 4.0, true,
                        "each pair's light index into its run", pairs});
    s.opWork.push_back({"light_bin_fill", Kind::BytesRead, Base::Items, 4.0, false,
                        "each light's index (at least: once per workgroup and dispatch that shares it)",
                        lights});
    for (Kind k : {Kind::BytesRead, Kind::BytesWritten})
        s.opWork.push_back({"light_bin_sort", k, Base::Items, 4.0, false,
                            "every run once (at least: a long run by steps)", pairs});
}

} // namespace tp::la
