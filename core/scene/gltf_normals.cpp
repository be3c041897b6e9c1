// Normals and tangents a glTF primitive lacks or has broken: flat or smooth normals from the
// faces, tangents from the uvs (gltf_geometry.cpp calls them while it reads a primitive).
#include <cmath>

#include "core/scene/gltf_internal.h"

namespace tp::gltf {
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    float len2 = glm::dot(v, v);
    if (!(len2 > 1e-30f) || !std::isfinite(len2)) return fallback;
    return v / std::sqrt(len2);
}

glm::vec3 anyPerpendicular(const glm::vec3& n) {
    glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return safeNormalize(axis - n * glm::dot(n, axis), glm::vec3(1, 0, 0));
}

void makeFlatNormals(LocalPrimitive& p) {
    deindex(p.positions, p.indices);
    deindex(p.tangents, p.indices);
    deindex(p.uvs, p.indices);
    deindex(p.colors, p.indices);
    p.normals.assign(p.positions.size(), glm::vec3(0, 1, 0));
    for (uint32_t i = 0; i < p.indices.size(); ++i)
        p.indices[i] = i;
    for (size_t t = 0; t + 2 < p.positions.size(); t += 3) {
        glm::vec3 n =
            glm::cross(p.positions[t + 1] - p.positions[t], p.positions[t + 2] - p.positions[t]);
        p.normals[t] = p.normals[t + 1] = p.normals[t + 2] = safeNormalize(n, glm::vec3(0, 1, 0));
    }
}

void makeSmoothNormals(const std::vector<glm::vec3>& positions,
                       const std::vector<uint32_t>& indices, std::vector<glm::vec3>& normals) {
    normals.assign(positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        // Unnormalized: the cross product's length is twice the area, hence area weighting.
        glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3& n : normals)
        n = safeNormalize(n, glm::vec3(0, 1, 0));
}

// MikkTSpace (what Blender and the glTF sample viewer use) is not packaged for Debian, so
// this is Lengyel's method; results match MikkTSpace's on well-behaved uv layouts and differ
// slightly on seams and skewed uvs.
void makeTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                  const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& indices,
                  std::vector<glm::vec4>& tangents) {
    std::vector<glm::vec3> sdir(positions.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> tdir(positions.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        glm::vec3 e1 = positions[b] - positions[a], e2 = positions[c] - positions[a];
        // v is negated: glTF's v grows down the image, the normal map's +Y (green) points up.
        glm::vec2 d1 = uvs[b] - uvs[a], d2 = uvs[c] - uvs[a];
        d1.y = -d1.y;
        d2.y = -d2.y;
        float r = d1.x * d2.y - d2.x * d1.y;
        if (r == 0.0f || !std::isfinite(r)) continue;
        // dP/du and dP/dv times |r|: weighted by uv area, so that near-degenerate uv
        // triangles cannot dominate a vertex.
        float sign = r > 0.0f ? 1.0f : -1.0f;
        glm::vec3 s = (e1 * d2.y - e2 * d1.y) * sign;
        glm::vec3 u = (e2 * d1.x - e1 * d2.x) * sign;
        for (uint32_t v : {a, b, c}) {
            sdir[v] += s;
            tdir[v] += u;
        }
    }
    tangents.resize(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3& n = normals[i];
        glm::vec3 t = sdir[i] - n * glm::dot(n, sdir[i]);
        float len2 = glm::dot(t, t);
        if (!(len2 > 1e-12f * std::max(glm::dot(sdir[i], sdir[i]), 1e-30f)) ||
            !std::isfinite(len2)) {
            tangents[i] = glm::vec4(anyPerpendicular(n), 1.0f);
            continue;
        }
        t /= std::sqrt(len2);
        float w = glm::dot(glm::cross(n, t), tdir[i]) < 0.0f ? -1.0f : 1.0f;
        tangents[i] = glm::vec4(t, w);
    }
}

} // namespace tp::gltf
