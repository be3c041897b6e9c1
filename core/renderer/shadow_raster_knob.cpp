#include "core/renderer/shadow_raster_knob.h"

namespace tp {

const ChoiceKnob<ShadowRaster>& shadowRasterKnob() {
    static const ChoiceKnob<ShadowRaster> k{
        "shadow-raster",
        {{ShadowRaster::Hardware, "hardware"}, {ShadowRaster::Compute, "compute"}},
        "Who rasterizes the shadow maps with --shadows: hardware (the graphics pipeline, one "
        "indirect draw per face and draw) or compute (compute shaders rasterize the meshlets "
        "the face cull kept, small triangles an invocation each, large ones a workgroup each, "
        "the depth as a 32-bit atomic max per texel, which the shading reads from that buffer "
        "when the maps are rendered every frame (--shadow-cache off) and from the kept map, "
        "copied there once, when they are cached; needs "
        "--cull-geometry frustum or full and the atlas: not deferred's volumes nor multipass "
        "forward; the depth within 2^-10 relative of the hardware's where both show the same "
        "surface, edge texels aside, docs/shadows.md)"};
    return k;
}

} // namespace tp
