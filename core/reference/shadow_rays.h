#pragma once
// The reference's shadow rays on the GPU (docs/shadows.md, "Exact visibility: the ray-traced
// reference"): the BVH of core/reference/shadow_bvh.h uploaded once (ledger owner "reference")
// and bound in the reference pass's own set (TP_SET_PASS), for the TP_SHADOW_RAYS variants of
// reference.frag. Built only when some light is shadowed (LightGpu.shadow != 0).
#include <vector>

#include "core/gpu/frame_graph.h"
#include "core/gpu/resources.h"
#include "core/reference/shadow_bvh.h"
#include "core/renderer/renderer.h"

namespace tp {

class GpuContext;
class SceneGpu;

namespace ref {

// Whether any uploaded light casts a shadow: the reference then traces rays.
bool anyLightShadowed(const SceneGpu& scene);

class ShadowRayScene {
  public:
    ShadowRayScene(GpuContext& ctx, const SceneGpu& scene, const std::string& pass);
    // The set-TP_SET_PASS buffers of the TP_SHADOW_RAYS shaders.
    std::vector<ExternalBuffer> externals() const;
    void addStats(RendererStats& s) const;

  private:
    Buffer nodes_, triangles_;
    size_t nodeCount_ = 0, triangleCount_ = 0;
    uint32_t depth_ = 0;
    double buildMs_ = 0;
};

} // namespace ref
} // namespace tp
