// Meshlets with meshoptimizer: the builder and the cluster bounds. One of the two files that
// include meshoptimizer (STYLE.md, lesson 15: the other decodes EXT_meshopt_compression,
// gltf_meshopt.cpp), each using one of its parts.
#include "core/scene/meshlets.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include <meshoptimizer.h>

namespace tp {
namespace {

struct Corners {
    uint32_t a, b, c;
    bool operator==(const Corners&) const = default;
};

struct CornersHash {
    size_t operator()(const Corners& t) const {
        uint64_t h = t.a * 0x9E3779B97F4A7C15ull;
        h ^= (h >> 29) + t.b * 0xBF58476D1CE4E5B9ull;
        h ^= (h >> 31) + t.c * 0x94D049BB133111EBull;
        return size_t(h ^ (h >> 32));
    }
};

// Each triangle of `reordered` (the builder's output) found among the mesh's triangles by its
// corners. Triangles with the same three corners (duplicated geometry) are handed out in the
// mesh's order, each once, so the result is a permutation.
std::vector<uint32_t> findSourceTriangles(const std::vector<uint32_t>& source,
                                          const std::vector<uint32_t>& reordered) {
    const uint32_t triangles = uint32_t(reordered.size() / 3);
    std::unordered_map<Corners, uint32_t, CornersHash> first; // the next unclaimed of a key
    std::vector<uint32_t> next(triangles, ~0u);               // the one after it, ~0u: none
    first.reserve(triangles);
    for (uint32_t t = triangles; t-- > 0;) {
        const Corners key{source[t * 3], source[t * 3 + 1], source[t * 3 + 2]};
        auto [it, fresh] = first.try_emplace(key, t);
        if (!fresh) {
            next[t] = it->second;
            it->second = t;
        }
    }
    std::vector<uint32_t> out(triangles);
    for (uint32_t t = 0; t < triangles; ++t) {
        auto it = first.find({reordered[t * 3], reordered[t * 3 + 1], reordered[t * 3 + 2]});
        // meshoptimizer keeps each triangle's corners in order; anything else is a bug here.
        if (it == first.end() || it->second == ~0u)
            throw std::logic_error("buildMeshlets: a meshlet triangle is not the mesh's");
        out[t] = it->second;
        it->second = next[it->second];
    }
    return out;
}

} // namespace

MeshMeshlets buildMeshlets(const Mesh& mesh) {
    MeshMeshlets out;
    const size_t indexCount = mesh.indices.size() / 3 * 3;
    if (indexCount == 0 || mesh.positions.empty()) return out;
    const size_t maxMeshlets =
        meshopt_buildMeshletsBound(indexCount, kMeshletMaxVertices, kMeshletMaxTriangles);
    std::vector<meshopt_Meshlet> meshlets(maxMeshlets);
    std::vector<unsigned int> vertices(maxMeshlets * kMeshletMaxVertices);
    std::vector<unsigned char> triangles(maxMeshlets * kMeshletMaxTriangles * 3);
    const float* positions = &mesh.positions[0].x;
    const size_t count = meshopt_buildMeshlets(
        meshlets.data(), vertices.data(), triangles.data(), mesh.indices.data(), indexCount,
        positions, mesh.positions.size(), sizeof(glm::vec3), kMeshletMaxVertices,
        kMeshletMaxTriangles, kMeshletConeWeight);
    out.meshlets.reserve(count);
    out.indices.reserve(indexCount);
    for (size_t i = 0; i < count; ++i) {
        const meshopt_Meshlet& m = meshlets[i];
        const unsigned int* local = &vertices[m.vertex_offset];
        const unsigned char* tris = &triangles[m.triangle_offset];
        meshopt_Bounds b = meshopt_computeMeshletBounds(local, tris, m.triangle_count, positions,
                                                        mesh.positions.size(), sizeof(glm::vec3));
        Meshlet r;
        r.firstIndex = uint32_t(out.indices.size());
        r.triangleCount = m.triangle_count;
        r.vertexCount = m.vertex_count;
        r.center = glm::vec3(b.center[0], b.center[1], b.center[2]);
        // meshoptimizer's sphere leaves out the corners of zero-area triangles; they make no
        // fragment, but the sphere is to hold every vertex the draw reads.
        r.radius = b.radius;
        for (uint32_t v = 0; v < m.vertex_count; ++v)
            r.radius = std::max(r.radius, glm::length(mesh.positions[local[v]] - r.center));
        r.coneApex = glm::vec3(b.cone_apex[0], b.cone_apex[1], b.cone_apex[2]);
        r.coneAxis = glm::vec3(b.cone_axis[0], b.cone_axis[1], b.cone_axis[2]);
        r.coneCutoff = b.cone_cutoff;
        for (size_t k = 0; k < size_t(m.triangle_count) * 3; ++k)
            out.indices.push_back(local[tris[k]]);
        out.meshlets.push_back(r);
    }
    out.sourceTriangles = findSourceTriangles(mesh.indices, out.indices);
    return out;
}

} // namespace tp
