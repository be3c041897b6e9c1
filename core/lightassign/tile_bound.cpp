#include "core/lightassign/tile_bound.h"

#include <algorithm>
#include <cmath>

#include "include/light_binning.h"

namespace tp::la {

namespace {

// The unit-normal plane {sign * (clipRow - ndc * clipW) >= 0} (Gribb-Hartmann), normalised in
// double and then rounded once to float: the GPU reads the very same floats.
glm::vec4 edgePlane(const glm::dmat4& proj, int row, double edge, double sign) {
    glm::dvec4 r(proj[0][row], proj[1][row], proj[2][row], proj[3][row]);
    glm::dvec4 w(proj[0][3], proj[1][3], proj[2][3], proj[3][3]);
    glm::dvec4 plane = sign * (r - edge * w);
    return glm::vec4(plane / glm::length(glm::dvec3(plane)));
}

// The two bounding planes of every slab [i*tile, min((i+1)*tile, size)) along one axis:
// "ndc >= lower edge" planes into lo, "ndc <= upper edge" into hi.
void appendSlabs(std::vector<glm::vec4>& lo, std::vector<glm::vec4>& hi, const glm::dmat4& proj,
                 int row, bool flipY, uint32_t size, uint32_t tile, uint32_t count) {
    auto ndcOf = [&](double px) {
        double t = 2.0 * px / double(size);
        return flipY ? 1.0 - t : t - 1.0;
    };
    for (uint32_t i = 0; i < count; ++i) {
        double e0 = ndcOf(double(i * tile)), e1 = ndcOf(double(std::min((i + 1) * tile, size)));
        lo.push_back(edgePlane(proj, row, std::min(e0, e1), 1.0));
        hi.push_back(edgePlane(proj, row, std::max(e0, e1), -1.0));
    }
}

// First and last slab that the sphere meets; empty (first > last) when none.
// A sphere wholly in front of the eye (binInFront): the planes of one family are nested
// half-spaces, so "outside plane i" is monotone in i - true up to some slab for the family
// that bounds slabs from the far side (`before`), true from some slab on for the other
// (`after`) - and two bisections find the range (columns: before = hi, after = lo; rows, whose
// ndc falls as the index grows: before = lo, after = hi). Any other sphere: every slab is
// tested, since behind the eye the half-spaces of planes through the eye are not nested.
// The GPU runs the same searches, probe for probe (shaders/lightassign/bin_common.glsl:
// binSlabRange), so where float rounding makes a family non-monotone at a near-tie both
// sides still agree; a tie lies within the padding (include/light_binning.h), never at a
// tile the culling keeps.
void slabRange(const std::vector<glm::vec4>& slabs, uint32_t loFirst, uint32_t hiFirst,
               uint32_t count, bool flip, const glm::vec3& c, float r, int& first, int& last) {
    first = int(count);
    last = -1;
    if (gpu::binInFront(c, r)) {
        const uint32_t before = flip ? loFirst : hiFirst, after = flip ? hiFirst : loFirst;
        uint32_t lo = 0, hi = count; // the first slab that `before` does not exclude
        while (lo < hi) {
            const uint32_t mid = (lo + hi) / 2;
            if (gpu::binOutside(slabs[before + mid], c, r))
                lo = mid + 1;
            else
                hi = mid;
        }
        const uint32_t begin = lo;
        hi = count; // the first slab from `begin` on that `after` excludes
        while (lo < hi) {
            const uint32_t mid = (lo + hi) / 2;
            if (gpu::binOutside(slabs[after + mid], c, r))
                hi = mid;
            else
                lo = mid + 1;
        }
        if (begin < lo) {
            first = int(begin);
            last = int(lo) - 1;
        }
        return;
    }
    for (uint32_t i = 0; i < count; ++i) {
        if (gpu::binOutside(slabs[loFirst + i], c, r)) continue;
        if (gpu::binOutside(slabs[hiFirst + i], c, r)) continue;
        first = std::min(first, int(i));
        last = int(i);
    }
}

} // namespace

std::vector<glm::vec4> binSlabPlanes(const TileGrid& grid, const glm::mat4& proj) {
    const glm::dmat4 p(proj);
    std::vector<glm::vec4> colLo, colHi, rowLo, rowHi;
    appendSlabs(colLo, colHi, p, 0, false, grid.width, grid.tileSize, grid.tilesX);
    appendSlabs(rowLo, rowHi, p, 1, true, grid.height, grid.tileSize, grid.tilesY);
    std::vector<glm::vec4> all = colLo;
    all.insert(all.end(), colHi.begin(), colHi.end());
    all.insert(all.end(), rowLo.begin(), rowLo.end());
    all.insert(all.end(), rowHi.begin(), rowHi.end());
    return all;
}

std::vector<TileRect> conservativeTileRects(const TileGrid& grid, const glm::mat4& view,
                                            const glm::mat4& proj,
                                            const std::vector<gpu::LightGpu>& lights,
                                            const std::vector<uint32_t>& local) {
    std::vector<TileRect> rects(local.size());
    const std::vector<glm::vec4> slabs = binSlabPlanes(grid, proj);
    const uint32_t X = grid.tilesX, Y = grid.tilesY;
    for (size_t k = 0; k < local.size(); ++k) {
        const gpu::LightGpu& l = lights[local[k]];
        const glm::vec3 c = gpu::binViewCentre(view, l.position);
        const float r = gpu::binPaddedRadius(l.range, c);
        if (gpu::binBehindEye(c, r)) continue;
        TileRect& t = rects[k];
        slabRange(slabs, 0, X, X, false, c, r, t.x0, t.x1);
        if (t.x0 > t.x1) continue;
        slabRange(slabs, 2 * X, 2 * X + Y, Y, true, c, r, t.y0, t.y1);
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
            if (x < grid.tilesX && y < grid.tilesY)
                bound[y * grid.tilesX + x] = uint32_t(std::max<int64_t>(0, s));
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
