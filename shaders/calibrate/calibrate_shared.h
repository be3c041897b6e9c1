// The calibration microbenchmarks (core/calibrate/calibration.h, `triptych calibrate`): their
// bindings, push constants and kinds, shared by calibrate.comp and the C++ that dispatches it.
#ifndef TP_CALIBRATE_SHARED_H
#define TP_CALIBRATE_SHARED_H
#include "include/glsl_cpp.h"

#define TP_CAL_BINDING_SRC 0 // buffer vec4[]: what the reads read
#define TP_CAL_BINDING_DST 1 // buffer vec4[] (uint[] for the atomics): what the writes write

#define TP_CAL_GROUP_SIZE 256 // invocations per workgroup, every kind

// Kinds (TP_CAL_KIND, one shader variant each).
#define TP_CAL_READ 0          // each invocation sums `iterations` vec4 of src, grid-strided
#define TP_CAL_WRITE 1         // ... writes them to dst
#define TP_CAL_COPY 2          // ... copies them from src to dst
#define TP_CAL_CACHE_READ 3    // ... reads them from the first mask + 1 vec4 of src only
#define TP_CAL_FMA 4           // 8 independent vec4 FMA chains, `iterations` steps (calibrate_fma.glsl)
#define TP_CAL_SHARED_ATOMIC 5 // `iterations` atomicAdd to shared memory, spread over 256 words
#define TP_CAL_GLOBAL_ATOMIC 6 // `iterations` atomicAdd to dst words (mask + 1 of them)
#define TP_CAL_FRAGMENT_FMA 7  // TP_CAL_FMA's loop per pixel of a full-screen triangle (calibrate_fma.frag)

#ifndef TP_GLSL
namespace tp::gpu {
#endif

struct CalPush {
    uint stride;     // vec4 between an invocation's steps: the grid (streams), 1024 (cache read)
    uint iterations; // steps per invocation
    uint mask;       // index mask: the buffer's or window's length in vec4 (words) minus 1
    uint pad;
};

#ifndef TP_GLSL
static_assert(sizeof(CalPush) == 16);
} // namespace tp::gpu
#endif
#endif
