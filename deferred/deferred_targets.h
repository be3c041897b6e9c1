#pragma once
// The frame-graph resources the deferred passes share; filled while planning. Invalid
// handles are resources this scene/configuration does not need (left out).
#include <vector>

#include "core/gpu/frame_graph.h"
#include "core/lightassign/tile_grid.h"
#include "deferred/gbuffer_layout.h"

namespace tp {

struct DeferredTargets {
    GBufferLayout layout;
    std::vector<ResourceHandle> gbuffer; // colour targets in layout.colors order
    ResourceHandle gbufferDepth;         // depth the G-buffer pass writes (per sample under MSAA)
    ResourceHandle hdr, depth;           // the standard single-sample outputs
    VkFormat hdrFormat = VK_FORMAT_R32G32B32A32_SFLOAT; // hdr and hdr_msaa (--hdr fp32 | fp16)
    ResourceHandle hdrMsaa;            // per-sample radiance: blended scenes under MSAA only
    ResourceHandle tileStats;          // uvec4 per tile
    ResourceHandle transparentLists;   // blended scenes only: compact (include/light_assign.h)
    ResourceHandle debug;              // --debug only (tiled lighting)
    ResourceHandle edgeMask;           // volumes lighting under MSAA: 1x edge mask
    ResourceHandle volumeDepth;        // volumes lighting under MSAA: 1x depth the volumes test
    la::TileGrid grid;                 // the lighting tiles (one workgroup each)
    std::vector<uint32_t> listOffsets; // transparent lists: tileCount + 1 run offsets
    bool sampleRateGBuffer = false;    // --msaa-shading sample: the material at every sample
    // --debug: the G-buffer is read where no geometry is (its channel images), so it is cleared
    // there; otherwise every reader tests the sample's depth first, and a clear would be paid
    // for nothing (docs/deferred.md, "The G-buffer is not cleared").
    bool clearGBuffer = false;
    bool msaa() const { return layout.samples > 1; }
    // The blended forward pass under MSAA at --msaa-shading pixel: once per pixel and
    // primitive at the pixel centre, as Forward+'s and multipass's blended draws (per sample
    // at --msaa-shading sample; at 1x the one sample is the centre either way).
    bool blendedPerPixel() const { return msaa() && !sampleRateGBuffer; }
};

} // namespace tp
