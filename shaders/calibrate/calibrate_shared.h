// The calibration microbenchmarks (core/calibrate/calibration.h, `triptych calibrate`): their
// bindings, push constants and kinds, shared by calibrate.comp and the C++ that dispatches it.
#ifndef TP_CALIBRATE_SHARED_H
#define TP_CALIBRATE_SHARED_H
#include "include/glsl_cpp.h"

#define TP_CAL_BINDING_SRC 0 // buffer vec4[]: what the reads read
#define TP_CAL_BINDING_DST 1 // buffer vec4[] (uint[] for the atomics): what the writes write
#define TP_CAL_BINDING_TEXTURE 2 // sampler2D, RGBA8 (TP_CAL_TEXTURE_SIZE squared): what the fetches read
// sampler2DMS, D32 at 4x (TP_CAL_TEXTURE_SIZE squared): what image_read_msaa4 reads, as a pass
// reads a multisampled depth (tile_depth_bounds, light culling)
#define TP_CAL_BINDING_DEPTH_MSAA4 3

#define TP_CAL_TEXTURE_SIZE 1024 // the size of a material texture in the built-in courtyard

#define TP_CAL_GROUP_SIZE 256 // invocations per workgroup, every kind

// Kinds (TP_CAL_KIND, one shader variant each).
#define TP_CAL_READ 0          // each invocation sums `iterations` vec4 of src, grid-strided
#define TP_CAL_WRITE 1         // ... writes them to dst
#define TP_CAL_COPY 2          // ... copies them from src to dst
#define TP_CAL_CACHE_READ 3    // ... reads them from the first mask + 1 vec4 of src only
#define TP_CAL_FMA 4           // 8 independent vec4 FMA chains, `iterations` steps (calibrate_fma.glsl)
#define TP_CAL_SHARED_ATOMIC 5 // `iterations` atomicAdd to shared memory, spread over 256 words
#define TP_CAL_GLOBAL_ATOMIC 6 // `iterations` atomicAdd to dst words (mask + 1 of them)
#define TP_CAL_FRAGMENT_FMA 7  // TP_CAL_FMA's loop per pixel of a full-screen triangle (calibrate.frag)
#define TP_CAL_TEXTURE 8       // `iterations` bilinear fetches of the texture, neighbouring texels
#define TP_CAL_LIGHT_POINT 9   // `iterations` evalLight of a point light (light_model.h)
#define TP_CAL_LIGHT_SPOT 10   // ... of a spot light
#define TP_CAL_IMAGE_READ 15   // `iterations` texelFetch of the texture (one texel, no filter)
#define TP_CAL_IMAGE_READ_MSAA4 16 // `iterations` texels of the 4x depth, each its 4 samples by texelFetch
// Fragment kinds (calibrate.frag), drawn over TP_CAL_VERTEX's geometry.
#define TP_CAL_FRAGMENT_TEXTURE 11 // TP_CAL_TEXTURE per pixel, with texture() (derivatives)
#define TP_CAL_FRAGMENT_LIGHT_POINT 12
#define TP_CAL_FRAGMENT_LIGHT_SPOT 13
#define TP_CAL_FRAGMENT_FLAT 14 // one constant colour: what rasterisation and the ROPs cost
#define TP_CAL_FRAGMENT_FLAT3 17 // ... into three colour attachments (the G-buffer ceilings)

// Vertex kinds (calibrate.vert, TP_CAL_VERTEX).
#define TP_CAL_VERTEX_LAYERS 0 // one full-screen triangle per instance (`iterations` instances)
#define TP_CAL_VERTEX_GRID 1   // `stride` x `stride` cells of two triangles each, per instance
// The same grid drawn indexed: (stride + 1)^2 vertices, each shared by up to six triangles, so
// a device that reuses shaded vertices shades about one per two triangles (a mesh's rate).
#define TP_CAL_VERTEX_GRID_INDEXED 2

#ifndef TP_GLSL
namespace tp::gpu {
#endif

struct CalPush {
    uint stride;     // vec4 between an invocation's steps: the grid (streams), 1024 (cache
                     // read); cells per row (TP_CAL_VERTEX_GRID)
    uint iterations; // steps per invocation; instances (layers) of a draw
    uint mask;       // index mask: the buffer's or window's length in vec4 (words) minus 1
    uint pad;
};

#ifndef TP_GLSL
static_assert(sizeof(CalPush) == 16);
} // namespace tp::gpu
#endif
#endif
