#include "core/lightassign/tile_bound.h"

#include <algorithm>
#include <cmath>

namespace tp::la {

namespace {

// The plane {sign * (clipRow - ndc * clipW) >= 0} (Gribb-Hartmann) with its normal's length:
// sign = +1 for "ndc coordinate >= edge", -1 for "<= edge".
struct EdgePlane {
    glm::dvec4 plane;
    double length;
    // Signed distance of p, inward positive.
    double distance(const glm::dvec3& p) const { return (glm::dot(glm::dvec3(plane), p) + plane.w) / length; }
};

EdgePlane edgePlane(const glm::dmat4& proj, int row, double edge, double sign) {
    glm::dvec4 r(proj[0][row], proj[1][row], proj[2][row], proj[3][row]);
    glm::dvec4 w(proj[0][3], proj[1][3], proj[2][3], proj[3][3]);
    glm::dvec4 plane = sign * (r - edge * w);
    return {plane, glm::length(glm::dvec3(plane))};
}

// The two bounding planes of every slab [i*tile, min((i+1)*tile, size)) along one axis,
// computed once per grid rather than once per light and slab.
struct Slabs {
    std::vector<EdgePlane> lo, hi; // "ndc >= lower edge", "ndc <= upper edge"
};

Slabs makeSlabs(const glm::dmat4& proj, int row, bool flipY, uint32_t size, uint32_t tile, uint32_t count) {
    auto ndcOf = [&](double px) {
        double t = 2.0 * px / double(size);
        return flipY ? 1.0 - t : t - 1.0;
    };
    Slabs s;
    for (uint32_t i = 0; i < count; ++i) {
        double e0 = ndcOf(double(i * tile)), e1 = ndcOf(double(std::min((i + 1) * tile, size)));
        s.lo.push_back(edgePlane(proj, row, std::min(e0, e1), 1.0));
        s.hi.push_back(edgePlane(proj, row, std::max(e0, e1), -1.0));
    }
    return s;
}

// First and last slab that the sphere meets; empty (first > last) when none. Every slab is
// tested (no bisection): the half-spaces of planes through the eye are not nested behind it.
void slabRange(const Slabs& slabs, const glm::dvec3& c, double r, int& first, int& last) {
    first = int(slabs.lo.size());
    last = -1;
    for (size_t i = 0; i < slabs.lo.size(); ++i) {
        if (slabs.lo[i].distance(c) < -r) continue;
        if (slabs.hi[i].distance(c) < -r) continue;
        first = std::min(first, int(i));
        last = int(i);
    }
}

} // namespace

std::vector<TileRect> conservativeTileRects(const TileGrid& grid, const glm::mat4& view, const glm::mat4& proj,
                                            const std::vector<gpu::LightGpu>& lights,
                                            const std::vector<uint32_t>& local) {
    std::vector<TileRect> rects(local.size());
    const glm::dmat4 v(view), p(proj);
    const Slabs columns = makeSlabs(p, 0, false, grid.width, grid.tileSize, grid.tilesX);
    const Slabs rows = makeSlabs(p, 1, true, grid.height, grid.tileSize, grid.tilesY);
    for (size_t k = 0; k < local.size(); ++k) {
        const gpu::LightGpu& l = lights[local[k]];
        glm::dvec3 c = glm::dvec3(v * glm::dvec4(glm::dvec3(l.position), 1.0));
        // Far more padding than the GPU test's (relative 1e-4): float rounding on the GPU
        // can never make it keep a light this bound excludes.
        double r = double(l.range) * 1.001 + 1e-3 * glm::length(c) + 1e-4;
        if (c.z - r > 0.0) continue; // entirely behind the eye
        TileRect& t = rects[k];
        slabRange(columns, c, r, t.x0, t.x1);
        if (t.x0 > t.x1) continue;
        slabRange(rows, c, r, t.y0, t.y1);
    }
    return rects;
}

std::vector<uint32_t> countTileRects(const TileGrid& grid, const std::vector<TileRect>& rects) {
    // Difference array over the tile grid: +1 at each light's rectangle.
    std::vector<int64_t> diff(size_t(grid.tilesX + 1) * (grid.tilesY + 1), 0);
    const size_t W = grid.tilesX + 1;
    for (const TileRect& t : rects) {
        if (t.empty()) continue;
        diff[size_t(t.y0) * W + t.x0] += 1;
        diff[size_t(t.y0) * W + t.x1 + 1] -= 1;
        diff[size_t(t.y1 + 1) * W + t.x0] -= 1;
        diff[size_t(t.y1 + 1) * W + t.x1 + 1] += 1;
    }
    std::vector<uint32_t> bound(grid.count(), 0);
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

std::vector<uint32_t> conservativeTileBound(const TileGrid& grid, const glm::mat4& view,
                                            const glm::mat4& proj,
                                            const std::vector<gpu::LightGpu>& lights,
                                            const std::vector<uint32_t>& local) {
    return countTileRects(grid, conservativeTileRects(grid, view, proj, lights, local));
}

} // namespace tp::la
