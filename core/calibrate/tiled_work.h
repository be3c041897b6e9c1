#pragma once
// The counted work of a compute pass that culls lights per tile and shades the tile's pixels
// (core/passes/tiled_lighting: deferred's and the visibility buffer's tiled_lighting), from its
// tile statistics (docs/efficiency.md, "Placing a pass: what is counted"):
// - light evaluations of the MSAA edge samples beyond each edge pixel's first (the pixels' are
//   the renderer's own entry): the tiles' mean list per sample, an estimate as the pixels' is;
// - shared atomics: one atomicOr per light a tile keeps, one atomicAdd per edge pixel: at least
//   (the depth bounds' and a batched tile's again are not counted);
// - light-vs-tile tests: the candidates of every tile, at most (a tile without geometry tests
//   none); reported, not placed: no ceiling measures a test.
#include <cstdint>
#include <string>

#include "core/renderer/renderer.h"

namespace tp {

struct TiledCounts {
    std::string pass;
    double keptLights = 0; // the tiles' list lengths, summed
    double edgePixels = 0;
    double meanLights = 0; // per tile
    double candidates = 0; // light-vs-tile tests
    uint32_t samples = 1;
};

void addTiledWork(RendererStats& s, const TiledCounts& c);

} // namespace tp
