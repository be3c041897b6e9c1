#pragma once
// The frame-graph resources the deferred passes share; filled while planning. Invalid
// handles are resources this scene/configuration does not need (left out).
#include <vector>

#include "core/gpu/frame_graph.h"
#include "deferred/gbuffer_layout.h"

namespace tp {

struct DeferredTargets {
    GBufferLayout layout;
    std::vector<ResourceHandle> gbuffer; // colour targets in layout.colors order
    ResourceHandle gbufferDepth;         // depth the G-buffer pass writes (per sample under MSAA)
    ResourceHandle hdr, depth;           // the standard single-sample outputs
    ResourceHandle hdrMsaa;              // per-sample radiance: blended scenes under MSAA only
    ResourceHandle tileStats;            // uvec4 per tile
    ResourceHandle transparentLists;     // blended scenes only
    ResourceHandle debug;                // --debug only (tiled lighting)
    ResourceHandle edgeMask;             // volumes lighting under MSAA: 1x edge mask
    ResourceHandle volumeDepth;          // volumes lighting under MSAA: 1x depth the volumes test
    uint32_t tileSize = 16, tilesX = 0, tilesY = 0;
    uint32_t listStride = 1;             // uints per transparent list: count + capacity
    bool sampleRateGBuffer = false;      // --gbuffer-msaa sample: the material at every sample
    bool msaa() const { return layout.samples > 1; }
};

} // namespace tp
