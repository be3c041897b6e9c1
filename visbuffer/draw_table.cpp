#include "visbuffer/draw_table.h"

#include <algorithm>

#include "core/renderer/renderer.h"

namespace tp::vis {

uint32_t bitsFor(uint64_t n) {
    uint32_t bits = 1;
    while (bits < 64 && (uint64_t(1) << bits) < n)
        ++bits;
    return bits;
}

DrawTable makeDrawTable(const SceneGpu& scene, bool blended) {
    DrawTable t;
    for (DrawFilter f : {DrawFilter::Opaque, DrawFilter::Mask, DrawFilter::Blend}) {
        if (f == DrawFilter::Blend && !blended) break;
        std::vector<TableDraw>& out = f == DrawFilter::Opaque ? t.opaque
                                      : f == DrawFilter::Mask ? t.masked
                                                              : t.blended;
        for (const DrawItem* d : scene.drawList(f)) {
            const uint32_t row = uint32_t(t.rows.size());
            t.rows.push_back({d->firstIndex, d->vertexOffset, d->material, 0});
            out.push_back({d, row});
            t.maxTriangles = std::max(t.maxTriangles, d->indexCount / 3);
        }
    }
    t.triangleBits = bitsFor(t.maxTriangles);
    // Rows are stored + 1 (0: no geometry), so the row field holds 0 .. rows.
    const uint32_t rowBits = bitsFor(uint64_t(t.rows.size()) + 1);
    if (t.triangleBits + rowBits > TP_VIS_ID_BITS)
        throw RendererError("visbuffer: " + std::to_string(t.rows.size()) +
                            (blended ? " opaque, masked and blended" : " opaque and masked") +
                            " draws of up to " + std::to_string(t.maxTriangles) +
                            " triangles need " + std::to_string(t.triangleBits + rowBits) +
                            " id bits, more than the " + std::to_string(TP_VIS_ID_BITS) +
                            " an fp32 id holds exactly");
    if (t.rows.empty()) t.rows.push_back({}); // a buffer of one row: nothing names it
    return t;
}

} // namespace tp::vis
