#include "core/scene/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/util/math.h"

namespace tp::procgen {

namespace {

// Any unit vector perpendicular to n.
glm::vec3 perpendicular(const glm::vec3& n) {
    glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(a, n));
}

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    float l = glm::length(v);
    return l > 1e-12f ? v / l : fallback;
}

// A rectangle corner, corner+a, corner+a+b, corner+b whose front faces `facing`.
// The second edge keeps its direction (it carries -v), so a vertical `eb` keeps textures upright.
void addRect(MeshBuilder& b, glm::vec3 corner, glm::vec3 ea, glm::vec3 eb, const glm::vec3& facing,
             float texSize) {
    if (glm::dot(glm::cross(ea, eb), facing) < 0.0f) {
        corner += ea;
        ea = -ea;
    }
    glm::vec3 n = glm::normalize(glm::cross(ea, eb));
    glm::vec3 ua = glm::normalize(ea), ub = glm::normalize(eb);
    auto uvOf = [&](const glm::vec3& p) {
        return glm::vec2(glm::dot(p, ua), -glm::dot(p, ub)) / texSize;
    };
    glm::vec3 p[4] = {corner, corner + ea, corner + ea + eb, corner + eb};
    uint32_t i[4];
    for (int k = 0; k < 4; ++k)
        i[k] = b.vertex(p[k], n, uvOf(p[k]));
    b.quad(i[0], i[1], i[2], i[3]);
}

} // namespace

MeshBuilder::MeshBuilder(std::string name, uint32_t material) {
    mesh_.name = std::move(name);
    mesh_.material = material;
}

uint32_t MeshBuilder::vertex(const glm::vec3& position, const glm::vec3& normal,
                             const glm::vec2& uv) {
    mesh_.positions.push_back(position);
    mesh_.normals.push_back(safeNormalize(normal, glm::vec3(0, 1, 0)));
    mesh_.uvs.push_back(uv);
    return uint32_t(mesh_.positions.size() - 1);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c) {
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
}

void MeshBuilder::quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
}

Mesh MeshBuilder::finish() {
    size_t n = mesh_.positions.size();
    std::vector<glm::vec3> tsum(n, glm::vec3(0.0f)), bsum(n, glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < mesh_.indices.size(); t += 3) {
        uint32_t i0 = mesh_.indices[t], i1 = mesh_.indices[t + 1], i2 = mesh_.indices[t + 2];
        glm::vec3 e1 = mesh_.positions[i1] - mesh_.positions[i0];
        glm::vec3 e2 = mesh_.positions[i2] - mesh_.positions[i0];
        glm::vec2 d1 = mesh_.uvs[i1] - mesh_.uvs[i0], d2 = mesh_.uvs[i2] - mesh_.uvs[i0];
        float r = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(r) < 1e-12f) continue;
        float area = 0.5f * glm::length(glm::cross(e1, e2));
        glm::vec3 dpdu = safeNormalize((e1 * d2.y - e2 * d1.y) / r, glm::vec3(0.0f));
        glm::vec3 dpdv = safeNormalize((e2 * d1.x - e1 * d2.x) / r, glm::vec3(0.0f));
        for (uint32_t i : {i0, i1, i2}) {
            tsum[i] += dpdu * area;
            bsum[i] += dpdv * area;
        }
    }
    mesh_.tangents.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const glm::vec3& nrm = mesh_.normals[i];
        glm::vec3 t = tsum[i] - nrm * glm::dot(nrm, tsum[i]);
        t = safeNormalize(t, perpendicular(nrm));
        // The bitangent cross(n, t) * w must point along -dP/dv (image up).
        float w = glm::dot(glm::cross(nrm, t), bsum[i]) > 0.0f ? -1.0f : 1.0f;
        mesh_.tangents[i] = glm::vec4(t, w);
    }
    mesh_.colors.assign(n, glm::vec4(1.0f));
    return std::move(mesh_);
}

void addSurface(MeshBuilder& b, int nu, int nv, const SurfaceFn& position, const UvFn& uv,
                bool flip) {
    constexpr float e = 1e-3f;
    std::vector<uint32_t> ids;
    ids.reserve(size_t(nu + 1) * size_t(nv + 1));
    for (int j = 0; j <= nv; ++j) {
        float v = float(j) / float(nv);
        for (int i = 0; i <= nu; ++i) {
            float u = float(i) / float(nu);
            glm::vec3 pu = position(u + e, v) - position(u - e, v);
            glm::vec3 pv = position(u, v + e) - position(u, v - e);
            glm::vec3 n =
                safeNormalize(glm::cross(pu, pv), perpendicular(safeNormalize(pu, {1, 0, 0})));
            if (flip) n = -n;
            ids.push_back(b.vertex(position(u, v), n, uv(u, v)));
        }
    }
    auto at = [&](int i, int j) { return ids[size_t(j) * size_t(nu + 1) + size_t(i)]; };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            if (flip)
                b.quad(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
            else
                b.quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
        }
}

void addFacingQuad(MeshBuilder& b, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
                   const glm::vec3& n, const glm::vec3& uAxis, const glm::vec3& vAxis,
                   float texSize) {
    if (glm::dot(glm::cross(p1 - p0, p2 - p0), n) < 0.0f) std::swap(p1, p3);
    auto uvOf = [&](const glm::vec3& p) {
        return glm::vec2(glm::dot(p, uAxis), -glm::dot(p, vAxis)) / texSize;
    };
    uint32_t i0 = b.vertex(p0, n, uvOf(p0)), i1 = b.vertex(p1, n, uvOf(p1));
    uint32_t i2 = b.vertex(p2, n, uvOf(p2)), i3 = b.vertex(p3, n, uvOf(p3));
    b.quad(i0, i1, i2, i3);
}

void addBox(MeshBuilder& b, const glm::vec3& mn, const glm::vec3& mx, float texSize,
            uint32_t skipFaces, bool inside) {
    glm::vec3 d = mx - mn;
    glm::vec3 ex(d.x, 0, 0), ey(0, d.y, 0), ez(0, 0, d.z);
    struct Face {
        glm::vec3 corner, a, b, n;
    };
    const Face faces[6] = {
        {mn, ez, ey, {-1, 0, 0}},     {mn + ex, ez, ey, {1, 0, 0}}, {mn, ex, ez, {0, -1, 0}},
        {mn + ey, ex, ez, {0, 1, 0}}, {mn, ex, ey, {0, 0, -1}},     {mn + ez, ex, ey, {0, 0, 1}},
    };
    for (int f = 0; f < 6; ++f) {
        if (skipFaces & (1u << f)) continue;
        // On vertical faces the second edge is the vertical one, so v runs down world y.
        addRect(b, faces[f].corner, faces[f].a, faces[f].b, inside ? -faces[f].n : faces[f].n,
                texSize);
    }
}

void addLathe(MeshBuilder& b, const glm::vec3& base, std::span<const glm::vec2> profile,
              int segments, int rows, float texSize) {
    const int count = int(profile.size());
    if (count < 2) return;
    std::vector<float> arc(size_t(count), 0.0f);
    float rmax = 0.0f;
    for (int k = 1; k < count; ++k)
        arc[k] = arc[k - 1] + glm::length(profile[k] - profile[k - 1]);
    for (const glm::vec2& p : profile)
        rmax = std::max(rmax, p.x);
    auto sample = [&](float v, float* s) {
        float t = v * float(count - 1);
        int k = std::clamp(int(std::floor(t)), 0, count - 2);
        float f = t - float(k);
        if (s) *s = arc[k] + f * (arc[k + 1] - arc[k]);
        return profile[k] + f * (profile[k + 1] - profile[k]);
    };
    auto pos = [&](float u, float v) {
        glm::vec2 p = sample(v, nullptr);
        float phi = u * 2.0f * kPi;
        return base + glm::vec3(p.x * std::cos(phi), p.y, -p.x * std::sin(phi));
    };
    auto uv = [&](float u, float v) {
        float s = 0.0f;
        sample(v, &s);
        return glm::vec2(u * 2.0f * kPi * rmax, -s) / texSize;
    };
    addSurface(b, segments, rows, pos, uv);
}

void addWall(MeshBuilder& b, const glm::vec3& origin, const glm::vec3& right, const glm::vec3& up,
             float width, float height, float thickness, std::span<const Rect> openings,
             float texSize) {
    const glm::vec3 n = glm::cross(right, up);
    const glm::vec3 back = -n * thickness;
    std::vector<float> xs = {0.0f, width}, ys = {0.0f, height};
    for (const Rect& r : openings) {
        xs.insert(xs.end(), {r.x0, r.x1});
        ys.insert(ys.end(), {r.y0, r.y1});
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    auto inOpening = [&](float x, float y) {
        for (const Rect& r : openings)
            if (x > r.x0 && x < r.x1 && y > r.y0 && y < r.y1) return true;
        return false;
    };
    auto at = [&](float x, float y) { return origin + right * x + up * y; };
    // Per band between two breakpoints in y, one rectangle per run of solid cells.
    for (size_t j = 0; j + 1 < ys.size(); ++j) {
        const float ym = 0.5f * (ys[j] + ys[j + 1]);
        for (size_t i = 0; i + 1 < xs.size();) {
            if (inOpening(0.5f * (xs[i] + xs[i + 1]), ym)) {
                ++i;
                continue;
            }
            size_t k = i + 1;
            while (k + 1 < xs.size() && !inOpening(0.5f * (xs[k] + xs[k + 1]), ym))
                ++k;
            glm::vec3 c = at(xs[i], ys[j]);
            glm::vec3 ea = right * (xs[k] - xs[i]), eb = up * (ys[j + 1] - ys[j]);
            addRect(b, c, ea, eb, n, texSize);
            addRect(b, c + back, ea, eb, -n, texSize);
            i = k;
        }
    }
    for (const Rect& r : openings) {
        const glm::vec3 w = right * (r.x1 - r.x0), h = up * (r.y1 - r.y0);
        if (r.y0 > 0.0f) addRect(b, at(r.x0, r.y0), w, back, up, texSize);
        addRect(b, at(r.x0, r.y1), w, back, -up, texSize);
        addRect(b, at(r.x0, r.y0), back, h, right, texSize);
        addRect(b, at(r.x1, r.y0), back, h, -right, texSize);
    }
    glm::vec3 fw = right * width, fh = up * height;
    // The bottom edge, except under doors (openings from y = 0), where it would show.
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
        float xm = 0.5f * (xs[i] + xs[i + 1]);
        bool door = false;
        for (const Rect& r : openings)
            door |= r.y0 <= 0.0f && xm > r.x0 && xm < r.x1;
        if (!door) addRect(b, at(xs[i], 0), right * (xs[i + 1] - xs[i]), back, -up, texSize);
    }
    addRect(b, at(0, height), fw, back, up, texSize);
    addRect(b, at(0, 0), back, fh, -right, texSize);
    addRect(b, at(width, 0), back, fh, right, texSize);
}

void addQuad(MeshBuilder& b, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
             const glm::vec3& p3, const glm::vec2& uv0, const glm::vec2& uv2, int n, int m) {
    auto pos = [&](float u, float v) {
        return (1 - v) * ((1 - u) * p0 + u * p1) + v * ((1 - u) * p3 + u * p2);
    };
    auto uv = [&](float u, float v) { return glm::mix(uv0, uv2, glm::vec2(u, v)); };
    addSurface(b, n, m, pos, uv);
}

} // namespace tp::procgen
