// Every struct, binding number and constant that crosses between C++ and GLSL.
// GLSL: std430 for storage buffers, std140 for the uniform buffer; C++ mirrors them with
// glm types and static_asserts on size and offsets (no bool fields: GLSL bool is 4 bytes).
#ifndef TP_SHARED_H
#define TP_SHARED_H
#include "include/glsl_cpp.h"

// ---- descriptor set 0: the scene, uploaded once and shared by every pipeline ----
#define TP_SET_SCENE 0
#define TP_BINDING_FRAME 0     // uniform FrameUniforms
#define TP_BINDING_VERTICES 1  // buffer Vertex[]
#define TP_BINDING_MATERIALS 2 // buffer MaterialGpu[]
#define TP_BINDING_LIGHTS 3    // buffer LightGpu[]
#define TP_BINDING_TEXTURES 4  // sampler2D[TP_SPEC_TEXTURE_COUNT]
// ---- descriptor set 1: the pipeline's own resources ----
#define TP_SET_PASS 1

// ---- specialization constant ids (shared by all pipelines) ----
#define TP_SPEC_TEXTURE_COUNT 0 // length of the texture array (>= 1)
#define TP_SPEC_HAS_SPOT 1      // 0: the spot-light code path is compiled out
#define TP_SPEC_ALPHA_MODE 2    // draws of one pipeline object share one alpha mode
// Constants every pipeline that has them shares, one id each (a pass library's passes set
// them without knowing which pipeline composed them):
#define TP_SPEC_TILE_SIZE 3     // tile edge in pixels (8, 16, 32: --tile) of the tiled light assignment
#define TP_SPEC_SAMPLES 4       // MSAA samples per pixel a pass reads (depth, G-buffer)
// A material's five texture indices compiled in (material.glsl, TP_MATERIAL_SPEC_TEXTURES):
// ids FIRST + 0..4 = base colour, metallic-roughness, normal, occlusion, emissive; the
// default TP_TEXTURE_FROM_MATERIAL reads the index from the material buffer instead.
#define TP_SPEC_MATERIAL_TEXTURE_FIRST 40
#define TP_TEXTURE_FROM_MATERIAL -2

// Light types and alpha modes (match tp::LightType / tp::AlphaMode).
#define TP_LIGHT_POINT 0u
#define TP_LIGHT_SPOT 1u
#define TP_LIGHT_DIRECTIONAL 2u
#define TP_ALPHA_OPAQUE 0u
#define TP_ALPHA_MASK 1u
#define TP_ALPHA_BLEND 2u
#define TP_NO_TEXTURE -1

// Numerical safety of the light model (documented in docs/shading.md).
#define TP_MIN_ROUGHNESS 0.03f     // perceptual roughness floor: keeps GGX D finite
#define TP_MIN_LIGHT_DISTANCE 0.01f // inverse-square falloff clamped at 1 cm

#ifndef TP_GLSL
namespace tp::gpu {
#endif

// Vertex pulling: one interleaved vertex, uv split across the two w components so the
// struct packs to 64 bytes with no std430 padding.
TP_STRUCT(Vertex) {
    vec4 positionU; // xyz position (world space), w = uv.x
    vec4 normalV;   // xyz normal, w = uv.y
    vec4 tangent;   // xyz tangent, w = bitangent sign
    vec4 color;     // COLOR_0 (linear)
};

TP_STRUCT(MaterialGpu) {
    vec4 baseColorFactor;
    vec3 emissive;   // factor (strength folded in)
    float alphaCutoff;
    float metallic;
    float roughness;
    float normalScale;
    float occlusionStrength;
    int baseColorTexture; // index into the texture array or TP_NO_TEXTURE
    int metallicRoughnessTexture;
    int normalTexture;
    int occlusionTexture;
    int emissiveTexture;
    uint alphaMode;
    uint doubleSided;
    uint pad0;
};

TP_STRUCT(LightGpu) {
    vec3 position;
    float range;
    vec3 direction; // where the light points (spot, directional), normalized
    uint type;
    vec3 color;     // linear colour times intensity
    uint shadow;    // 0: casts no shadow; else 1 + its first ShadowFace (include/shadows.h)
    float spotScale;  // 1 / max(1e-4, cos(inner) - cos(outer))
    float spotOffset; // -cos(outer) * spotScale
    float pad1;
    float pad2;
};

// std140 uniform buffer: mat4 and vec4 only.
// Camera-relative (docs/shading.md, "Camera-relative shading"): as uploaded, every position
// the shaders see is world position minus the eye: scene.vert subtracts eyeWorld from the
// (world-space) vertices, LightGpu.position is uploaded relative to the eye (in double on
// the CPU), `view` is the rotation only (the eye at the origin) and viewProj / invViewProj
// are built from it; the viewer is at the origin (toViewer = -position). Only scene.vert
// may use eyeWorld. SceneGpu::frame() keeps a world-space copy for CPU code.
TP_STRUCT(FrameUniforms) {
    mat4 view;        // camera-relative -> view space: rotation only
    mat4 proj;
    mat4 viewProj;    // proj * view: camera-relative -> clip
    mat4 invProj;
    mat4 invViewProj; // clip -> camera-relative
    vec4 eyeWorld;    // xyz: the eye in world space (scene.vert's subtraction only), w unused
    vec4 ambient;        // rgb ambient radiance
    uvec4 viewport;      // width, height, light count, msaa samples
    vec4 projParams;     // znear, zfar (0 = infinite), one (1.0: scene.vert's outOne), unused
};

// Push constant of every scene draw.
TP_STRUCT(DrawPush) {
    uint materialIndex;
    uint pad0;
    uint pad1;
    uint pad2;
};

#ifndef TP_GLSL
static_assert(sizeof(Vertex) == 64);
static_assert(sizeof(MaterialGpu) == 80);
static_assert(offsetof(MaterialGpu, alphaCutoff) == 28);
static_assert(offsetof(MaterialGpu, baseColorTexture) == 48);
static_assert(offsetof(MaterialGpu, alphaMode) == 68);
static_assert(sizeof(LightGpu) == 64);
static_assert(offsetof(LightGpu, range) == 12);
static_assert(offsetof(LightGpu, type) == 28);
static_assert(offsetof(LightGpu, spotScale) == 48);
static_assert(sizeof(FrameUniforms) == 5 * 64 + 4 * 16);
static_assert(offsetof(FrameUniforms, viewport) == 5 * 64 + 32);
static_assert(sizeof(DrawPush) == 16);
} // namespace tp::gpu
#endif

// Pipeline-free: each pipeline's own structs, set-TP_SET_PASS bindings and constants live
// in its own header beside its shaders (shaders/<pipeline>/<pipeline>_shared.h), included
// by that pipeline's C++ and GLSL only.
#endif
