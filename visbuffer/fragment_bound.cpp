#include "visbuffer/fragment_bound.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/gpuscene/scene_gpu.h"
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

namespace {

// A convex polygon of at most 8 vertices: a triangle cut by the near plane (4), then by the
// four screen edges (one more each).
struct Poly {
    glm::dvec2 p[8];
    int n = 0;
};

// Sutherland-Hodgman against sign * (q[axis] - at) <= 0, in place of clipTo's vectors.
Poly clipPoly(const Poly& in, int axis, double at, double sign) {
    Poly out;
    for (int i = 0; i < in.n; ++i) {
        const glm::dvec2 p = in.p[i], q = in.p[(i + 1) % in.n];
        const double dp = sign * (p[axis] - at), dq = sign * (q[axis] - at);
        if (dp <= 0) out.p[out.n++] = p;
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0))
            out.p[out.n++] = p + (q - p) * (dp / (dp - dq));
    }
    return out;
}

// Pixel centres a convex screen polygon can contain: triangleCentreBound's argument (area +
// L1 perimeter / 2 + 1 of its part on the screen, at most its box's centres).
double polyCentreBound(Poly poly, uint32_t width, uint32_t height) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int i = 0; i < poly.n; ++i) {
        lo = glm::min(lo, poly.p[i]);
        hi = glm::max(hi, poly.p[i]);
    }
    auto centres = [](double a, double b, uint32_t size) {
        const double first = std::max(0.0, std::ceil(a - 0.5));
        const double last = std::min(double(size) - 1.0, std::floor(b - 0.5));
        return last >= first ? last - first + 1.0 : 0.0;
    };
    const double box = centres(lo.x, hi.x, width) * centres(lo.y, hi.y, height);
    if (box == 0.0) return 0.0;
    poly = clipPoly(poly, 0, 0.0, -1.0);
    poly = clipPoly(poly, 0, double(width), 1.0);
    poly = clipPoly(poly, 1, 0.0, -1.0);
    poly = clipPoly(poly, 1, double(height), 1.0);
    double twiceArea = 0.0, l1 = 0.0;
    for (int i = 0; i < poly.n; ++i) {
        const glm::dvec2 p = poly.p[i], q = poly.p[(i + 1) % poly.n];
        twiceArea += p.x * q.y - p.y * q.x;
        l1 += std::abs(q.x - p.x) + std::abs(q.y - p.y);
    }
    return std::min(box, std::ceil(std::abs(twiceArea) * 0.5 + l1 * 0.5 + 1.0));
}

// Whether every corner of the box lies clearly outside one plane of the clip volume (-w <= x,
// y <= w, w >= wMin): each is linear in the position, so the whole box does then.
bool boxOutside(const glm::mat4& viewProj, const Aabb& box, double wMin) {
    int out[5] = {0, 0, 0, 0, 0};
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 c((k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
                          (k & 4) ? box.max.z : box.min.z);
        const glm::dvec4 h = glm::dvec4(viewProj * glm::vec4(c, 1.0f));
        const double e = 1e-4 * (std::abs(h.w) + 1.0); // fp32 rounding: only clearly outside
        out[0] += h.x < -h.w - e;
        out[1] += h.x > h.w + e;
        out[2] += h.y < -h.w - e;
        out[3] += h.y > h.w + e;
        out[4] += h.w < wMin - e;
    }
    for (int n : out)
        if (n == 8) return true;
    return false;
}

// One triangle in clip space, cut to w >= wMin, projected to pixels.
double clippedTriangleBound(const glm::dvec4* h, double wMin, uint32_t width, uint32_t height) {
    glm::dvec4 kept[4];
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec4 p = h[i], q = h[(i + 1) % 3];
        const double dp = p.w - wMin, dq = q.w - wMin;
        if (dp >= 0) kept[n++] = p;
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) kept[n++] = p + (q - p) * (dp / (dp - dq));
    }
    if (n < 3) return 0.0;
    Poly poly;
    poly.n = n;
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 ndc = glm::dvec2(kept[i]) / kept[i].w;
        poly.p[i] = (ndc * 0.5 + 0.5) * glm::dvec2(width, height);
    }
    return polyCentreBound(poly, width, height);
}

} // namespace

uint64_t viewFragmentBound(const SceneGpu& scene, const std::vector<TableDraw>& blended,
                           uint32_t width, uint32_t height, uint32_t samples) {
    const gpu::FrameUniforms& f = scene.shadingFrame();
    const double wMin = std::max(0.5 * double(f.projParams.x), 1e-6); // znear / 2
    double total = 0.0;
    std::vector<glm::dvec4> clip;
    for (const TableDraw& d : blended) {
        if (boxOutside(f.viewProj, scene.toShading(d.item->bounds), wMin)) continue;
        const Mesh& m = scene.scene().meshes[d.item->mesh];
        clip.resize(m.positions.size());
        for (size_t v = 0; v < m.positions.size(); ++v)
            clip[v] = glm::dvec4(f.viewProj * glm::vec4(scene.toShading(m.positions[v]), 1.0f));
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            const glm::dvec4 h[3] = {clip[m.indices[t]], clip[m.indices[t + 1]],
                                     clip[m.indices[t + 2]]};
            total += clippedTriangleBound(h, wMin, width, height);
        }
    }
    return uint64_t(total) * samples;
}

} // namespace tp::vis
