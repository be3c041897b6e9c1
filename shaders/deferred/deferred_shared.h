// G-buffer deferred: structs, set-1 bindings and constants shared by C++ and GLSL.
// Included by this pipeline's C++ and GLSL only (never by shared.h); same rules as
// shared.h (TP_STRUCT, static_asserts on the C++ side).
#ifndef TP_DEFERRED_SHARED_H
#define TP_DEFERRED_SHARED_H
#include "include/shared.h"
#include "passes/tiled_lighting.h"
#ifndef TP_GLSL
#include <cmath>
namespace tp::gpu {
using std::cos;
using std::sin;
#endif
#define TP_PI_DEF 3.14159265358979f

// ---- set 1 of the tiled lighting pass: the G-buffer's bindings (passes/tiled_lighting.h
// leaves these to the surface source); the light volumes use the same ----
#define TP_DEF_BINDING_BASE 0        // sampler: base colour rgb + occlusion a
#define TP_DEF_BINDING_NORMAL 1      // sampler: octahedral normal (compact) or xyz (wide)
#define TP_DEF_BINDING_ROUGH_METAL 2 // sampler: roughness r, metallic g
#define TP_DEF_BINDING_EMISSIVE 3    // sampler: emissive rgb (only when the scene emits)
#define TP_DEF_BINDING_EDGE_MASK 9   // sampler: 1x edge mask (volumes lighting under MSAA)
// The G-buffer pass's own set: the materials' uniform-buffer copy (core/passes/materials_ubo.h),
// read where TP_DEF_SPEC_MATERIALS_UBO.
#define TP_DEF_BINDING_MATERIALS_UBO 20
#define TP_DEF_SPEC_MATERIALS_UBO 36

#define TP_DEF_SPEC_WIDE 11          // 1: wide (fp32, xyz normal) G-buffer, 0: compact
// ---- specialization constants of the light-volume shaders ----
#define TP_DEF_SPEC_SPHERE_SCALE 14  // float bits: volumeSphereVertex scale that circumscribes the unit sphere

// ---- light volumes (classic deferred, `--deferred-lighting volumes`) ----
// Generated from gl_VertexIndex in shaders/deferred/volume.vert; the CPU computes the scale
// that makes the sphere mesh circumscribe the unit sphere and tests both meshes
// (tests/cpu/deferred_volume_mesh_test.cpp). Triangles wind counter-clockwise seen from
// outside, i.e. they are front faces under the scene's conventions (core/gpu/pipelines.h).
#define TP_DEF_SPHERE_STACKS 8u
#define TP_DEF_SPHERE_SLICES 16u
#define TP_DEF_SPHERE_VERTICES (TP_DEF_SPHERE_STACKS * TP_DEF_SPHERE_SLICES * 6u)
#define TP_DEF_CONE_SEGMENTS 16u
#define TP_DEF_CONE_VERTICES (TP_DEF_CONE_SEGMENTS * 6u) // sides + cap fan around its centre

// A UV sphere on the unit sphere (vertices on it: the mesh is inside; scale it by the
// CPU-computed factor to circumscribe). Two triangles per stack x slice quad (one of them
// degenerate at the poles).
TP_INLINE vec3 volumeSphereVertex(uint k) {
    const uint corners[6] = {0u, 1u, 2u, 0u, 2u, 3u}; // (i,j) (i+1,j) (i+1,j+1) (i,j+1)
    uint quad = k / 6u;
    uint c = corners[k % 6u];
    uint i = quad / TP_DEF_SPHERE_SLICES + ((c == 1u || c == 2u) ? 1u : 0u);
    uint j = quad % TP_DEF_SPHERE_SLICES + ((c == 2u || c == 3u) ? 1u : 0u);
    float lat = -0.5f * TP_PI_DEF + TP_PI_DEF * float(i) / float(TP_DEF_SPHERE_STACKS);
    float lon = 2.0f * TP_PI_DEF * float(j) / float(TP_DEF_SPHERE_SLICES);
    return vec3(cos(lat) * cos(lon), sin(lat), cos(lat) * sin(lon));
}

// A cone with its apex at the origin, axis +z, cap at z = 1, whose 16-gon cross-section
// circumscribes the circle of radius 1 at z = 1: it contains the round cone of slope 1.
TP_INLINE vec3 volumeConeVertex(uint k) {
    uint segment = (k / 3u) % TP_DEF_CONE_SEGMENTS;
    uint corner = k % 3u;
    bool cap = k >= TP_DEF_CONE_SEGMENTS * 3u;
    if (corner == 0u) return cap ? vec3(0.0f, 0.0f, 1.0f) : vec3(0.0f);
    // Sides: apex, ring j+1, ring j; cap: centre, ring j, ring j+1 (both outward CCW).
    uint j = segment + ((corner == 1u) != cap ? 1u : 0u);
    float a = 2.0f * TP_PI_DEF * float(j) / float(TP_DEF_CONE_SEGMENTS);
    float r = 1.0f / cos(TP_PI_DEF / float(TP_DEF_CONE_SEGMENTS));
    return vec3(r * cos(a), r * sin(a), 1.0f);
}

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
