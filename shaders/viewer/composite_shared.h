// The viewer's scene area composed on the GPU (viewer/gpu_composite.h): the split view, flip
// and the difference heat map from the renderers' images where they are, and the two figures
// the composite needs from them (auto exposure's log-average, the heat map's 99th percentile),
// shared by composite.comp, composite_stats.comp and the C++ that dispatches them.
#ifndef TP_VIEWER_COMPOSITE_SHARED_H
#define TP_VIEWER_COMPOSITE_SHARED_H
#include "include/glsl_cpp.h"

#define TP_VC_BINDING_LEFT 0  // sampler2D: the left image (split), A (difference), linear HDR
#define TP_VC_BINDING_RIGHT 1 // sampler2D: the right image (split), B (difference)
#define TP_VC_BINDING_OUT 2   // buffer uint[]: RGBA8 per pixel, row 0 at the top (composite.comp)
#define TP_VC_BINDING_STATS 3 // buffer uint[]: the stats (composite_stats.comp); the ramp (composite.comp)

#define TP_VC_GROUP 16 // 16 x 16 invocations a workgroup, both shaders

#define TP_VC_SPLIT 0
#define TP_VC_DIFFERENCE 1

// composite_stats.comp's kinds (TP_VC_STATS):
#define TP_VC_LOG_LUMINANCE 0 // per workgroup: the sum of log(luminance) and the count (2 words)
#define TP_VC_HIGH_HISTOGRAM 1 // 65,536 bins of a finite max-channel |A - B|'s high 16 bits, then the count
#define TP_VC_LOW_HISTOGRAM 2  // 65,536 bins of the low 16 bits, of the values whose high bits are `prefix`

#define TP_VC_RAMP_COLOURS 10 // the heat map's ramp (core/image/difference.h heatRamp), vec4 each

#ifndef TP_GLSL
namespace tp::gpu {
#endif

TP_STRUCT(CompositePush) {
    uint width;      // the scene rows' size (the legend rows below are copied in, not composed)
    uint height;
    uint mode;       // TP_VC_SPLIT, TP_VC_DIFFERENCE
    uint boundary;   // split: the first column of the right image
    uint divider;    // split: the divider's column; 0xffffffff: none
    uint sides;      // bit 0: the left image is bound, bit 1: the right one
    uint swapRB;     // 1: the target is BGRA (a swapchain)
    uint prefix;     // TP_VC_LOW_HISTOGRAM's high bits
    float exposureEv;
    float diffScale; // the heat map's upper end (difference)
    float pad0, pad1;
};

#ifndef TP_GLSL
static_assert(sizeof(CompositePush) == 48);
} // namespace tp::gpu
#endif
#endif
