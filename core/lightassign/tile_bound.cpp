#include "core/lightassign/tile_bound.h"

#include <algorithm>
#include <cmath>

namespace tp::la {

namespace {

// Signed distance (inward positive) of p from the plane {clipRow - ndc * clipW >= 0}
// (Gribb-Hartmann), sign = +1 for "ndc coordinate >= edge", -1 for "<= edge".
double planeDistance(const glm::dmat4& proj, int row, double edge, double sign, const glm::dvec3& p) {
    glm::dvec4 r(proj[0][row], proj[1][row], proj[2][row], proj[3][row]);
    glm::dvec4 w(proj[0][3], proj[1][3], proj[2][3], proj[3][3]);
    glm::dvec4 plane = sign * (r - edge * w);
    double len = glm::length(glm::dvec3(plane));
    return (glm::dot(glm::dvec3(plane), p) + plane.w) / len;
}

// First and last slab [i*tile, min((i+1)*tile, size)) along one axis that the sphere meets;
// empty (first > last) when none.
void slabRange(const glm::dmat4& proj, int row, bool flipY, uint32_t size, uint32_t tile, uint32_t count,
               const glm::dvec3& c, double r, int& first, int& last) {
    first = int(count);
    last = -1;
    auto ndcOf = [&](double px) {
        double t = 2.0 * px / double(size);
        return flipY ? 1.0 - t : t - 1.0;
    };
    for (uint32_t i = 0; i < count; ++i) {
        double e0 = ndcOf(double(i * tile)), e1 = ndcOf(double(std::min((i + 1) * tile, size)));
        double lo = std::min(e0, e1), hi = std::max(e0, e1);
        if (planeDistance(proj, row, lo, 1.0, c) < -r) continue;
        if (planeDistance(proj, row, hi, -1.0, c) < -r) continue;
        first = std::min(first, int(i));
        last = int(i);
    }
}

} // namespace

std::vector<uint32_t> conservativeTileBound(const TileGrid& grid, const glm::mat4& view,
                                            const glm::mat4& proj,
                                            const std::vector<gpu::LightGpu>& lights,
                                            const std::vector<uint32_t>& local) {
    // Difference array over the tile grid: +1 at each light's rectangle.
    std::vector<int64_t> diff(size_t(grid.tilesX + 1) * (grid.tilesY + 1), 0);
    const glm::dmat4 v(view), p(proj);
    for (uint32_t index : local) {
        const gpu::LightGpu& l = lights[index];
        glm::dvec3 c = glm::dvec3(v * glm::dvec4(glm::dvec3(l.position), 1.0));
        // Far more padding than the GPU test's (relative 1e-4): float rounding on the GPU
        // can never make it keep a light this bound excludes.
        double r = double(l.range) * 1.001 + 1e-3 * glm::length(c) + 1e-4;
        if (c.z - r > 0.0) continue; // entirely behind the eye
        int x0, x1, y0, y1;
        slabRange(p, 0, false, grid.width, grid.tileSize, grid.tilesX, c, r, x0, x1);
        if (x0 > x1) continue;
        slabRange(p, 1, true, grid.height, grid.tileSize, grid.tilesY, c, r, y0, y1);
        if (y0 > y1) continue;
        const size_t W = grid.tilesX + 1;
        diff[size_t(y0) * W + x0] += 1;
        diff[size_t(y0) * W + x1 + 1] -= 1;
        diff[size_t(y1 + 1) * W + x0] -= 1;
        diff[size_t(y1 + 1) * W + x1 + 1] += 1;
    }
    std::vector<uint32_t> bound(grid.count(), 0);
    const size_t W = grid.tilesX + 1;
    std::vector<int64_t> acc(diff.size(), 0);
    for (uint32_t y = 0; y <= grid.tilesY; ++y)
        for (uint32_t x = 0; x <= grid.tilesX; ++x) {
            int64_t s = diff[y * W + x];
            if (x > 0) s += acc[y * W + x - 1];
            if (y > 0) s += acc[(y - 1) * W + x];
            if (x > 0 && y > 0) s -= acc[(y - 1) * W + x - 1];
            acc[y * W + x] = s;
            if (x < grid.tilesX && y < grid.tilesY) bound[y * grid.tilesX + x] = uint32_t(std::max<int64_t>(0, s));
        }
    return bound;
}

} // namespace tp::la
