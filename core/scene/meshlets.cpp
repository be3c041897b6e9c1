// Meshlets with meshoptimizer: the builder and the cluster bounds. One of the two files that
// include meshoptimizer (STYLE.md, lesson 15: the other decodes EXT_meshopt_compression,
// gltf_meshopt.cpp), each using one of its parts.
#include "core/scene/meshlets.h"

#include <algorithm>
#include <stdexcept>

#include <meshoptimizer.h>

namespace tp {
namespace {

// Each triangle of `reordered` (the builder's output) found among the mesh's triangles by its
// corners (`source`, the mesh's index list). The mesh's triangles are bucketed by their first
// corner (a counting sort: flat arrays, no hashing, a few candidates per vertex); copies of one
// triangle (the same corners) are handed out in the mesh's order, each once, so the result is a
// permutation.
std::vector<uint32_t> findSourceTriangles(const std::vector<uint32_t>& source,
                                          const std::vector<uint32_t>& reordered) {
    const uint32_t triangles = uint32_t(reordered.size() / 3);
    uint32_t vertices = 0;
    for (uint32_t t = 0; t < triangles; ++t)
        vertices = std::max(vertices, source[t * 3] + 1);
    std::vector<uint32_t> first(size_t(vertices) + 1, 0); // bucket starts, by first corner
    for (uint32_t t = 0; t < triangles; ++t)
        ++first[source[t * 3] + 1];
    for (uint32_t v = 0; v < vertices; ++v)
        first[v + 1] += first[v];
    std::vector<uint32_t> bucket(triangles), fill(first.begin(), first.end() - 1);
    for (uint32_t t = 0; t < triangles; ++t)
        bucket[fill[source[t * 3]]++] = t; // ascending within a bucket
    std::vector<bool> claimed(triangles, false);
    std::vector<uint32_t> out(triangles, ~0u);
    for (uint32_t t = 0; t < triangles; ++t) {
        const uint32_t a = reordered[t * 3], b = reordered[t * 3 + 1], c = reordered[t * 3 + 2];
        for (uint32_t k = a < vertices ? first[a] : 0; a < vertices && k < first[a + 1]; ++k) {
            const uint32_t s = bucket[k];
            if (claimed[s] || source[s * 3 + 1] != b || source[s * 3 + 2] != c) continue;
            claimed[s] = true;
            out[t] = s;
            break;
        }
        // meshoptimizer keeps each triangle's corners in order; anything else is a bug here.
        if (out[t] == ~0u)
            throw std::logic_error("buildMeshlets: a meshlet triangle is not the mesh's");
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
