#include "triangle_pixels.h"

#include <algorithm>
#include <cmath>

#include "core/camera/camera.h"
#include "core/camera/pixel_position.h"

namespace tp::test {
namespace {

struct Front {
    double depth = 0.0;        // reverse-Z: larger is nearer; 0 is nothing
    uint64_t triangle = 0;     // 1 + mesh << 32 | triangle index
    double edgeDistance = 1e9; // pixels, from the sample to the nearest edge of its triangle
};

struct ScreenTriangle {
    glm::dvec3 v[3]; // framebuffer x, y (pixels, y down) and reverse-Z depth
};

// Depth at p by the triangle's screen-space barycentrics (depth is affine in screen space);
// false outside it.
bool depthAt(const ScreenTriangle& t, glm::dvec2 p, double& depth, double& edgeDistance) {
    double e[3], len[3];
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 a(t.v[k]), b(t.v[(k + 1) % 3]);
        e[k] = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        len[k] = std::max(glm::length(b - a), 1e-300);
    }
    const double area = e[0] + e[1] + e[2];
    if (area == 0.0) return false;
    const bool inside =
        (e[0] >= 0 && e[1] >= 0 && e[2] >= 0) || (e[0] <= 0 && e[1] <= 0 && e[2] <= 0);
    if (!inside) return false;
    // e[k] is twice the area opposite vertex (k + 2) % 3.
    depth = (e[1] * t.v[0].z + e[2] * t.v[1].z + e[0] * t.v[2].z) / area;
    edgeDistance =
        std::min({std::abs(e[0]) / len[0], std::abs(e[1]) / len[1], std::abs(e[2]) / len[2]});
    return true;
}

// Sutherland-Hodgman against the near plane w - z >= 0: the part of the triangle in front.
std::vector<glm::dvec4> clipToNearPlane(const glm::dvec4 (&clip)[3]) {
    std::vector<glm::dvec4> out;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec4 &a = clip[k], &b = clip[(k + 1) % 3];
        const double da = a.w - a.z, db = b.w - b.z;
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// Every sample of every pixel in the triangle's box: the triangle where it is the front one.
void rasterize(const ScreenTriangle& t, uint64_t id, uint32_t width, uint32_t height,
               uint32_t samples, std::vector<Front>& front) {
    const double x0 = std::min({t.v[0].x, t.v[1].x, t.v[2].x}),
                 x1 = std::max({t.v[0].x, t.v[1].x, t.v[2].x}),
                 y0 = std::min({t.v[0].y, t.v[1].y, t.v[2].y}),
                 y1 = std::max({t.v[0].y, t.v[1].y, t.v[2].y});
    const int px0 = std::max(0, int(std::floor(x0))), px1 = std::min(int(width) - 1, int(x1));
    const int py0 = std::max(0, int(std::floor(y0))), py1 = std::min(int(height) - 1, int(y1));
    for (int y = py0; y <= py1; ++y)
        for (int x = px0; x <= px1; ++x)
            for (uint32_t s = 0; s < samples; ++s) {
                const glm::dvec2 p = glm::dvec2(x, y) + standardSampleOffset(samples, s);
                double depth = 0.0, edge = 0.0;
                if (!depthAt(t, p, depth, edge) || depth < 0.0 || depth > 1.0) continue;
                Front& f = front[(size_t(y) * width + size_t(x)) * samples + s];
                if (depth > f.depth) f = {depth, id, edge};
            }
}

} // namespace

TrianglePixels findManyTrianglePixels(const Scene& scene, uint32_t width, uint32_t height,
                                      uint32_t samples, double margin) {
    const glm::dmat4 viewProj =
        glm::dmat4(reverseZPerspective(scene.camera.yfov, float(double(width) / double(height)),
                                       scene.camera.znear, scene.camera.zfar)) *
        viewMatrixWorld(scene.camera);
    std::vector<Front> front(size_t(width) * height * samples);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        // Blended surfaces write no depth: the position either shading takes is the opaque one.
        if (scene.materials[mesh.material].alphaMode == AlphaMode::Blend) continue;
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            // Clipped to the near plane (reverse-Z: depth z / w <= 1, i.e. w - z >= 0), so
            // that a floor reaching behind the eye still covers the pixels it covers; a fan of
            // at most two triangles, one id.
            const uint64_t id = 1 + (uint64_t(m) << 32 | uint64_t(i / 3));
            glm::dvec4 clip[3];
            for (int k = 0; k < 3; ++k)
                clip[k] =
                    viewProj * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i + k]]), 1.0);
            const std::vector<glm::dvec4> polygon = clipToNearPlane(clip);
            for (size_t k = 1; k + 1 < polygon.size(); ++k) {
                ScreenTriangle t;
                const glm::dvec4* v[3] = {&polygon[0], &polygon[k], &polygon[k + 1]};
                for (int j = 0; j < 3; ++j)
                    t.v[j] = {(v[j]->x / v[j]->w * 0.5 + 0.5) * width,
                              (0.5 - v[j]->y / v[j]->w * 0.5) * height, v[j]->z / v[j]->w};
                rasterize(t, id, width, height, samples, front);
            }
        }
    }

    TrianglePixels out;
    out.manyTriangles.assign(size_t(width) * height, 0);
    for (size_t p = 0; p < out.manyTriangles.size(); ++p) {
        const Front* f = &front[p * samples];
        bool many = false;
        for (uint32_t s = 0; s < samples && !many; ++s)
            many =
                f[s].triangle != f[0].triangle || (f[s].depth > 0.0 && f[s].edgeDistance <= margin);
        out.manyTriangles[p] = many;
    }
    return out;
}

} // namespace tp::test
