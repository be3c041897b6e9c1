#pragma once
// A shadow plan as the scene on the GPU holds it (docs/shadows.md): which lights cast shadows,
// their faces and the atlas they pack into. What it holds, not how it is made: the planner
// (core/passes/shadow_planner.h) makes it from the uploaded lights and frame, the frame runner
// gives it to SceneGpu (SceneGpu::setShadows), and the passes and reports read it back.
#include <cstdint>
#include <vector>

#include "include/shadows.h"

namespace tp {

struct ShadowLight {
    uint32_t light = 0;     // index in the scene's lights
    uint32_t firstFace = 0; // in ShadowPlan::faces
    uint32_t faceCount = 0; // 6 (cube) or 1 (spot)
    uint32_t edge = 0;      // texels per face edge
    double influence = 0.0; // screen pixels of its reach (the selection's key)
};

struct ShadowPlan {
    std::vector<ShadowLight> lights; // most influential first
    std::vector<gpu::ShadowFace> faces;
    uint32_t atlasWidth = 0, atlasHeight = 0; // the resident atlas (D32: 4 bytes a texel)
    uint32_t localWidth = 0, localHeight = 0; // one light's map, the largest light's block
    uint32_t requested = 0;                   // N, or the candidates for `all`
    bool empty() const { return lights.empty(); }
    uint64_t atlasBytes() const { return uint64_t(atlasWidth) * atlasHeight * 4; }
    uint64_t localBytes() const { return uint64_t(localWidth) * localHeight * 4; }
    uint64_t faceTexels() const; // what the faces cover (the atlas has no gaps but rounding)
    // The same layout: the same lights with the same map sizes, the same atlas (a renderer that
    // sized its maps for one layout plans again when it changes: SceneGpu::shadowGeneration).
    bool operator==(const ShadowPlan& o) const;
    // The layout, and every face and light word as uploaded: nothing to upload again.
    bool sameUpload(const ShadowPlan& o) const;
};

} // namespace tp
