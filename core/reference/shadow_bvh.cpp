#include "core/reference/shadow_bvh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

namespace tp::ref {
namespace {

constexpr int kSahBins = 16;

struct BvhChild {
    Aabb box;
    uint32_t index = 0;
    uint32_t info = 0;
};

float bvhHalfArea(const Aabb& b) {
    if (b.empty()) return 0.0f;
    glm::vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

// Moved outward by a millionth of its largest coordinate, so the shader's fp32 slab test never
// rejects a box whose triangle the ray hits (a floor's box has no thickness at all).
Aabb bvhPadded(Aabb b) {
    glm::vec3 m = glm::max(glm::abs(b.min), glm::abs(b.max));
    float pad = std::max(std::max(m.x, m.y), m.z) * 1e-6f + 1e-30f;
    b.min -= glm::vec3(pad);
    b.max += glm::vec3(pad);
    return b;
}

class BvhBuilder {
  public:
    BvhBuilder(const std::vector<glm::vec3>& positions,
               const std::vector<gpu::ShadowTriangle>& triangles)
        : order_(triangles.size()) {
        boxes_.resize(triangles.size());
        centroids_.resize(triangles.size());
        for (size_t i = 0; i < triangles.size(); ++i) {
            const gpu::ShadowTriangle& t = triangles[i];
            for (uint32_t v : {t.v0, t.v1, t.v2}) boxes_[i].extend(positions.at(v));
            centroids_[i] = boxes_[i].center();
            order_[i] = uint32_t(i);
        }
    }

    // [begin, end) under one child: leaves of at most leafMax triangles, tagged leafFlags.
    BvhChild build(uint32_t begin, uint32_t end, uint32_t depth) {
        Aabb box;
        for (uint32_t i = begin; i < end; ++i) box.extend(boxes_[order_[i]]);
        if (end == begin) return {box, 0, TP_SHADOW_BVH_LEAF}; // empty: no triangle to test
        if (end - begin <= leafMax_)
            return {bvhPadded(box), begin, TP_SHADOW_BVH_LEAF | leafFlags_ | (end - begin)};
        const uint32_t node = uint32_t(nodes_.size());
        nodes_.emplace_back();
        depth_ = std::max(depth_, depth + 1);
        const uint32_t mid = split(begin, end, depth);
        const BvhChild a = build(begin, mid, depth + 1);
        const BvhChild b = build(mid, end, depth + 1);
        gpu::ShadowBvhNode& n = nodes_[node];
        n = {a.box.min, a.index, a.box.max, a.info, b.box.min, b.index, b.box.max, b.info};
        return {bvhPadded(box), node, 0};
    }

    std::vector<gpu::ShadowBvhNode> nodes_;
    std::vector<uint32_t> order_;
    uint32_t depth_ = 0;
    uint32_t leafMax_ = TP_SHADOW_BVH_LEAF_MAX, leafFlags_ = 0;

  private:
    // Where [begin, end) splits: the binned-SAH plane, or the median of the widest centroid
    // axis where the levels left (TP_SHADOW_BVH_MAX_DEPTH) could not absorb a poor SAH split.
    uint32_t split(uint32_t begin, uint32_t end, uint32_t depth) {
        Aabb cb;
        for (uint32_t i = begin; i < end; ++i) cb.extend(centroids_[order_[i]]);
        const glm::vec3 ext = cb.extent();
        const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
        const uint32_t n = end - begin;
        const bool medianOnly = depth + 2 + uint32_t(std::ceil(std::log2(double(n)))) >=
                                TP_SHADOW_BVH_MAX_DEPTH;
        if (ext[axis] > 0.0f && !medianOnly) {
            int bestAxis = -1, bestBin = 0;
            sahPlane(begin, end, cb, bestAxis, bestBin);
            if (bestAxis >= 0) return partition(begin, end, cb, bestAxis, bestBin);
        }
        const uint32_t mid = begin + n / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                         [&](uint32_t x, uint32_t y) {
                             return centroids_[x][axis] < centroids_[y][axis];
                         });
        return mid;
    }

    int binOf(uint32_t tri, const Aabb& cb, int axis) const {
        const float e = cb.max[axis] - cb.min[axis];
        if (e <= 0.0f) return 0;
        const int b = int(float(kSahBins) * (centroids_[tri][axis] - cb.min[axis]) / e);
        return std::clamp(b, 0, kSahBins - 1);
    }

    // The plane (axis, last bin on the left) of least count x area over the three axes.
    void sahPlane(uint32_t begin, uint32_t end, const Aabb& cb, int& bestAxis, int& bestBin) const {
        float best = INFINITY;
        for (int axis = 0; axis < 3; ++axis) {
            if (cb.max[axis] <= cb.min[axis]) continue;
            Aabb box[kSahBins];
            uint32_t count[kSahBins] = {};
            for (uint32_t i = begin; i < end; ++i) {
                const int b = binOf(order_[i], cb, axis);
                box[b].extend(boxes_[order_[i]]);
                ++count[b];
            }
            float rightCost[kSahBins] = {};
            Aabb r;
            uint32_t rc = 0;
            for (int b = kSahBins - 1; b > 0; --b) {
                r.extend(box[b]);
                rc += count[b];
                rightCost[b] = float(rc) * bvhHalfArea(r);
            }
            Aabb l;
            uint32_t lc = 0;
            for (int b = 0; b < kSahBins - 1; ++b) {
                l.extend(box[b]);
                lc += count[b];
                const float cost = float(lc) * bvhHalfArea(l) + rightCost[b + 1];
                if (lc > 0 && lc < end - begin && cost < best) {
                    best = cost;
                    bestAxis = axis;
                    bestBin = b;
                }
            }
        }
    }

    uint32_t partition(uint32_t begin, uint32_t end, const Aabb& cb, int axis, int bin) {
        auto it = std::partition(order_.begin() + begin, order_.begin() + end,
                                 [&](uint32_t t) { return binOf(t, cb, axis) <= bin; });
        return uint32_t(it - order_.begin());
    }

    std::vector<Aabb> boxes_;
    std::vector<glm::vec3> centroids_;
};

} // namespace

ShadowBvhInput shadowBvhInput(const Scene& scene) {
    ShadowBvhInput in;
    in.positions.reserve(scene.vertexCount());
    for (const Mesh& mesh : scene.meshes) {
        const uint32_t base = uint32_t(in.positions.size());
        in.positions.insert(in.positions.end(), mesh.positions.begin(), mesh.positions.end());
        const Material& mat = scene.materials.at(mesh.material);
        if (mat.alphaMode == AlphaMode::Blend) continue;
        const uint32_t material =
            mat.alphaMode == AlphaMode::Mask ? mesh.material : TP_SHADOW_OPAQUE;
        for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
            in.triangles.push_back({base + mesh.indices[i], base + mesh.indices[i + 1],
                                    base + mesh.indices[i + 2], material});
    }
    return in;
}

ShadowBvh buildShadowBvh(const std::vector<glm::vec3>& positions,
                         const std::vector<gpu::ShadowTriangle>& triangles) {
    const auto start = std::chrono::steady_clock::now();
    BvhBuilder b(positions, triangles);
    // Opaque triangles first: the root's child a holds them, child b the masked ones.
    auto masked = std::stable_partition(b.order_.begin(), b.order_.end(), [&](uint32_t t) {
        return triangles[t].material == TP_SHADOW_OPAQUE;
    });
    const uint32_t n = uint32_t(triangles.size()), opaque = uint32_t(masked - b.order_.begin());
    b.nodes_.emplace_back();
    const BvhChild a = b.build(0, opaque, 1);
    b.leafMax_ = 1; // a masked leaf is one triangle: the shader alpha-tests it on its own
    b.leafFlags_ = TP_SHADOW_BVH_MASKED;
    const BvhChild m = b.build(opaque, n, 1);
    b.nodes_[0] = {a.box.min, a.index, a.box.max, a.info, m.box.min, m.index, m.box.max, m.info};
    ShadowBvh out;
    out.nodes = std::move(b.nodes_);
    out.depth = std::max(b.depth_, 1u);
    out.triangles.reserve(n);
    for (uint32_t i : b.order_) out.triangles.push_back(triangles[i]);
    out.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                            start).count();
    return out;
}

bool shadowRayBlocked(const ShadowBvh& bvh, const std::vector<glm::vec3>& positions,
                      glm::vec3 origin, glm::vec3 target, uint32_t* steps) {
    const glm::vec3 d = target - origin;
    const glm::vec3 inv = gpu::shadowRayInvDir(d);
    auto triangleHit = [&](uint32_t i) {
        const gpu::ShadowTriangle& t = bvh.triangles[i];
        const glm::vec3 h =
            gpu::rayTriangle(origin, d, positions[t.v0], positions[t.v1], positions[t.v2]);
        return h.x > 0.0f && h.x < 1.0f;
    };
    // The shader's order: pop an entry; a masked leaf is tested on its own, an inner node tests
    // both children's boxes, its opaque leaves at once, and pushes the rest.
    uint32_t stack[TP_SHADOW_BVH_STACK];
    uint32_t sp = 0, visits = 0;
    stack[sp++] = 0;
    bool blocked = false;
    while (sp > 0 && !blocked) {
        ++visits;
        const uint32_t entry = stack[--sp];
        if (entry & TP_SHADOW_BVH_LEAF) {
            blocked = triangleHit(entry & ~TP_SHADOW_BVH_LEAF);
            continue;
        }
        const gpu::ShadowBvhNode& n = bvh.nodes[entry];
        for (auto [lo, hi, index, info] : {std::tuple{n.aMin, n.aMax, n.a, n.aInfo},
                                           std::tuple{n.bMin, n.bMax, n.b, n.bInfo}}) {
            if (gpu::rayBoxEntry(origin, inv, 1.0f, lo, hi) > 1.0f) continue;
            const uint32_t count = info & TP_SHADOW_BVH_COUNT;
            if (info == 0)
                stack[sp++] = index;
            else if (info & TP_SHADOW_BVH_MASKED)
                stack[sp++] = TP_SHADOW_BVH_LEAF | index;
            else
                for (uint32_t k = 0; k < count && !blocked; ++k) blocked = triangleHit(index + k);
        }
    }
    if (steps) *steps = visits;
    return blocked;
}

} // namespace tp::ref
