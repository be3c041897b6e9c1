// G-buffer deferred: structs, set-1 bindings and constants shared by C++ and GLSL.
// Included by shared.h; same rules (TP_STRUCT, static_asserts on the C++ side).
#ifndef TP_DEFERRED_SHARED_H
#define TP_DEFERRED_SHARED_H
#ifndef TP_GLSL
namespace tp::gpu {
#endif

// ---- set 1 of the tiled lighting compute pass ----
#define TP_DEF_BINDING_BASE 0        // sampler: base colour rgb + occlusion a
#define TP_DEF_BINDING_NORMAL 1      // sampler: octahedral normal (compact) or xyz (wide)
#define TP_DEF_BINDING_ROUGH_METAL 2 // sampler: roughness r, metallic g
#define TP_DEF_BINDING_EMISSIVE 3    // sampler: emissive rgb (only when the scene emits)
#define TP_DEF_BINDING_DEPTH 4       // sampler: D32 depth (per sample under MSAA)
#define TP_DEF_BINDING_HDR 5         // storage image: lit radiance (RGBA32F)
#define TP_DEF_BINDING_TRANSPARENT_LISTS 6 // buffer: per-tile transparent light lists
#define TP_DEF_BINDING_DEBUG 7       // storage image RGBA32F: edge mask, roughness, metallic
#define TP_DEF_BINDING_TILE_STATS 8  // buffer uvec4 per tile: opaque lights, transparent lights, edge pixels, overflow

// ---- set 1 of the hybrid forward pass (blended materials) ----
#define TP_DEF_FWD_BINDING_LISTS 0   // buffer: per-tile transparent light lists

// ---- specialization constants of the deferred shaders (ids after the scene's 0..2) ----
#define TP_DEF_SPEC_TILE_SIZE 10     // tile edge in pixels (= workgroup edge)
#define TP_DEF_SPEC_WIDE 11          // 1: wide (fp32, xyz normal) G-buffer, 0: compact
#define TP_DEF_SPEC_LIST_STRIDE 12   // uints per transparent tile list: 1 (count) + capacity
#define TP_DEF_SPEC_SAMPLES 13       // MSAA samples of the G-buffer

// Lights one tile can hold in shared memory: 4096 uints = 16 KiB of the 32 KiB lavapipe
// offers. A tile that meets more lights does not drop them: it shades with every light
// (evalLight is exactly zero outside a light's range), and counts the overflow.
#define TP_DEF_TILE_LIGHT_CAPACITY 4096u

#ifndef TP_GLSL
} // namespace tp::gpu
#endif
#endif
