#pragma once
// The draws a visibility id can name (visbuffer/vis_shared.h): the opaque, then the
// alpha-masked draws of the scene, then (blended fragment lists) the blended draws back to
// front as the reference draws them, one VisDraw row each, and how an id's 24 bits split
// between the row and the triangle for this scene.
#include <cstdint>
#include <string>
#include <vector>

#include "core/gpuscene/scene_gpu.h"
#include "visbuffer/vis_shared.h"

namespace tp::vis {

struct TableDraw {
    const DrawItem* item;
    uint32_t row; // its VisDraw row (the push constant's pad0 in the visibility pass)
};

struct DrawTable {
    std::vector<gpu::VisDraw> rows;
    std::vector<TableDraw> opaque, masked; // in the order the visibility pass draws them
    std::vector<TableDraw> blended;        // in the reference's order: ascending rows
    uint32_t triangleBits = 1;             // low bits of an id: the triangle within its draw
    uint32_t maxTriangles = 0;             // of the largest draw
};

// Throws RendererError (one line, naming the counts) when the rows and the largest draw's
// triangles cannot share TP_VIS_ID_BITS with the value 0 kept for "no geometry".
// blended: the blended draws get rows too (--vis-blended compute).
DrawTable makeDrawTable(const SceneGpu& scene, bool blended);

// Bits to hold the values 0 .. n - 1 (at least 1).
uint32_t bitsFor(uint64_t n);

} // namespace tp::vis
