#include "visbuffer/fragment_bound.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/scene/scene.h"

namespace tp::vis {

namespace {

// Integer points x + 0.5 in [lo, hi] with 0 <= x < size.
double centresIn(float lo, float hi, uint32_t size) {
    const double first = std::max(0.0, std::ceil(double(lo) - 0.5));
    const double last = std::min(double(size) - 1.0, std::floor(double(hi) - 0.5));
    return last >= first ? last - first + 1.0 : 0.0;
}

// The convex polygon `poly` cut by the half-plane of points q with sign * (q[axis] - at) <= 0
// (Sutherland-Hodgman, one edge of the screen).
std::vector<glm::dvec2> clipTo(const std::vector<glm::dvec2>& poly, int axis, double at,
                               double sign) {
    std::vector<glm::dvec2> out;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % poly.size()];
        const double dp = sign * (p[axis] - at), dq = sign * (q[axis] - at);
        if (dp <= 0) out.push_back(p);
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    return out;
}

} // namespace

double triangleCentreBound(glm::vec2 a, glm::vec2 b, glm::vec2 c, uint32_t width,
                           uint32_t height) {
    const glm::vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const double box = centresIn(lo.x, hi.x, width) * centresIn(lo.y, hi.y, height);
    if (box == 0.0) return 0.0;
    // The part on the screen holds every centre the triangle does (they lie on the screen).
    std::vector<glm::dvec2> poly{glm::dvec2(a), glm::dvec2(b), glm::dvec2(c)};
    poly = clipTo(poly, 0, 0.0, -1.0);
    poly = clipTo(poly, 0, double(width), 1.0);
    poly = clipTo(poly, 1, 0.0, -1.0);
    poly = clipTo(poly, 1, double(height), 1.0);
    double twiceArea = 0.0, l1 = 0.0;
    for (size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % poly.size()];
        twiceArea += p.x * q.y - p.y * q.x;
        l1 += std::abs(q.x - p.x) + std::abs(q.y - p.y);
    }
    return std::min(box, std::ceil(std::abs(twiceArea) * 0.5 + l1 * 0.5 + 1.0));
}

uint64_t blendedFragmentBound(const SceneGpu& scene, const std::vector<TableDraw>& blended,
                              uint32_t width, uint32_t height, uint32_t samples) {
    const glm::mat4& viewProj = scene.shadingFrame().viewProj;
    const double screen = double(width) * height;
    double total = 0.0;
    for (const TableDraw& d : blended) {
        const Mesh& m = scene.scene().meshes[d.item->mesh];
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            glm::vec2 p[3];
            bool behind = false;
            for (int k = 0; k < 3; ++k) {
                const glm::vec4 clip =
                    viewProj * glm::vec4(scene.toShading(m.positions[m.indices[t + k]]), 1.0f);
                behind = behind || !(clip.w > 1e-6f);
                const glm::vec2 ndc = glm::vec2(clip) / clip.w;
                p[k] = (ndc * 0.5f + 0.5f) * glm::vec2(width, height);
            }
            total += behind ? screen : triangleCentreBound(p[0], p[1], p[2], width, height);
        }
    }
    return uint64_t(total) * samples;
}

} // namespace tp::vis
