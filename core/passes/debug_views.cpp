#include "core/passes/debug_views.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/image/difference.h"

namespace tp::passes {
namespace {

void outlineTile(ImageRGBA& img, const TileGrid& g, uint32_t tx, uint32_t ty) {
    uint32_t x0 = tx * g.tileSize, y0 = ty * g.tileSize;
    uint32_t x1 = std::min(x0 + g.tileSize, g.width) - 1,
             y1 = std::min(y0 + g.tileSize, g.height) - 1;
    for (uint32_t y = y0; y <= y1; ++y)
        for (uint32_t x = x0; x <= x1; ++x) {
            if (x != x0 && x != x1 && y != y0 && y != y1) continue;
            float* p = img.at(x, y);
            p[0] = 0.0f;
            p[1] = 1.0f;
            p[2] = 0.0f;
            p[3] = 1.0f;
        }
}

} // namespace

uint32_t heatMapScaleMax(const std::vector<uint32_t>& counts) {
    uint32_t m = 1;
    for (uint32_t c : counts)
        m = std::max(m, c);
    return m;
}

ImageRGBA lightsPerTileHeatMap(const TileGrid& g, const std::vector<uint32_t>& counts,
                               const std::vector<uint32_t>& dropped) {
    ImageRGBA values(g.width, g.height);
    for (uint32_t y = 0; y < g.height; ++y)
        for (uint32_t x = 0; x < g.width; ++x) {
            float* p = values.at(x, y);
            p[0] = p[1] = p[2] = float(counts[g.tileOf(x, y)]);
            p[3] = 1.0f;
        }
    ImageRGBA out = heatMap(values, float(heatMapScaleMax(counts)));
    if (dropped.empty()) return out;
    for (uint32_t ty = 0; ty < g.tilesY; ++ty)
        for (uint32_t tx = 0; tx < g.tilesX; ++tx)
            if (dropped[ty * g.tilesX + tx] > 0) outlineTile(out, g, tx, ty);
    return out;
}

ImageRGBA tileDepthBoundsImage(const TileGrid& g, const std::vector<TileDepthRange>& tiles,
                               const glm::mat4& invProj) {
    auto distance = [&](float depth) {
        glm::vec4 v = invProj * glm::vec4(0.0f, 0.0f, depth, 1.0f);
        return std::abs(v.w) < 1e-30f ? std::numeric_limits<float>::infinity() : -v.z / v.w;
    };
    const uint32_t gap = 4;
    ImageRGBA values(2 * g.width + gap, g.height);
    float farthest = 0.0f;
    for (const TileDepthRange& t : tiles)
        if (t.nearDepth > 0.0f) farthest = std::max(farthest, distance(t.farDepth));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (uint32_t y = 0; y < g.height; ++y)
        for (uint32_t x = 0; x < g.width; ++x) {
            const TileDepthRange& t = tiles[(y / g.tileSize) * g.tilesX + x / g.tileSize];
            bool sky = t.nearDepth <= 0.0f;
            float n = sky ? nan : distance(t.nearDepth), f = sky ? nan : distance(t.farDepth);
            float* a = values.at(x, y);
            float* b = values.at(g.width + gap + x, y);
            a[0] = a[1] = a[2] = n;
            b[0] = b[1] = b[2] = f;
            a[3] = b[3] = 1.0f;
        }
    return heatMap(values, farthest > 0.0f && std::isfinite(farthest) ? farthest : 1.0f);
}

} // namespace tp::passes
