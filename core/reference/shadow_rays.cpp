#include "core/reference/shadow_rays.h"

#include <algorithm>

#include "core/gpu/context.h"
#include "core/gpuscene/scene_gpu.h"

namespace tp::ref {

bool anyLightShadowed(const SceneGpu& scene) {
    const std::vector<gpu::LightGpu>& lights = scene.shadingLights();
    return std::any_of(lights.begin(), lights.end(),
                       [](const gpu::LightGpu& l) { return l.shadow != 0u; });
}

namespace {

// A storage buffer of at least one element (an empty scene still binds something).
template <class T>
Buffer uploadArray(GpuContext& ctx, const std::vector<T>& items, const LedgerTag& tag) {
    std::vector<T> data = items;
    if (data.empty()) data.push_back(T{});
    return createBufferWithData(ctx, data.data(), data.size() * sizeof(T),
                                VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, tag);
}

} // namespace

ShadowRayScene::ShadowRayScene(GpuContext& ctx, const SceneGpu& scene, const std::string& pass) {
    const ShadowBvhInput in = shadowBvhInput(scene.scene());
    const ShadowBvh bvh = buildShadowBvh(in.positions, in.triangles);
    nodeCount_ = bvh.nodes.size();
    triangleCount_ = bvh.triangles.size();
    depth_ = bvh.depth;
    buildMs_ = bvh.buildMs;
    nodes_ = uploadArray(ctx, bvh.nodes,
                         {"reference", pass, "shadow_bvh_nodes",
                          "shadow-ray BVH: inner nodes with both children's boxes"});
    triangles_ = uploadArray(ctx, bvh.triangles,
                             {"reference", pass, "shadow_bvh_triangles",
                              "shadow-ray BVH: opaque and masked triangles' vertex indices"});
}

std::vector<ExternalBuffer> ShadowRayScene::externals() const {
    return {{TP_BINDING_SHADOW_BVH_NODES, nodes_.buffer},
            {TP_BINDING_SHADOW_BVH_TRIANGLES, triangles_.buffer}};
}

void ShadowRayScene::addStats(RendererStats& s) const {
    s.counters.push_back({"shadow_bvh_nodes", double(nodeCount_)});
    s.counters.push_back({"shadow_bvh_triangles", double(triangleCount_)});
    s.counters.push_back({"shadow_bvh_depth", double(depth_)});
    s.counters.push_back({"shadow_bvh_build_ms", buildMs_});
}

} // namespace tp::ref
