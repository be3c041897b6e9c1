// Material evaluation at a fragment: textures, vertex colour, normal map, alpha; GLSL only.
// Every pipeline's fragment stage calls this, so surfaces are identical everywhere.
#ifndef TP_MATERIAL_GLSL
#define TP_MATERIAL_GLSL
#include "include/light_model.h"

struct MaterialSample {
    SurfaceSample surface;
    vec3 emissive;
    float occlusion;
    float alpha;
};

// A fragment stage samples with the hardware's derivatives and takes the geometric normal from
// dFdx/dFdy. A compute stage has neither: it defines these four before including this file
// (the visibility buffer's resolve, visbuffer/vis_read.glsl: textureGrad with analytic
// gradients, and a material index that differs between invocations).
#ifndef TP_MATERIAL_TEXTURE
#define TP_MATERIAL_TEXTURE(index, uv) texture(textures[index], uv)
#endif
#ifndef TP_MATERIAL_POSITION_DX
#define TP_MATERIAL_POSITION_DX(p) dFdx(p)
#define TP_MATERIAL_POSITION_DY(p) dFdy(p)
#endif

vec4 sampleTexture(int index, vec2 uv, vec4 fallback) {
    if (index < 0 || index >= kTextureCount) return fallback;
    return TP_MATERIAL_TEXTURE(index, uv);
}

// TP_MATERIAL_SPEC_TEXTURES: the five texture indices are specialization constants, one
// pipeline per material (core/passes/material_pipelines.h: Forward+'s shading and the blended
// forward pass). lavapipe runs
// both sides of every branch, so sampleTexture()'s guard does not skip the sample of an absent
// texture, and it takes a dynamic index through a per-lane loop and a switch over the whole
// array; compiled in, an absent texture costs nothing and a present one is a static sample
// (docs/forwardplus.md, "The material floor on lavapipe"). A slot left at
// TP_TEXTURE_FROM_MATERIAL reads the buffer as before; either way the same texel is sampled.
#ifdef TP_MATERIAL_SPEC_TEXTURES
layout(constant_id = TP_SPEC_MATERIAL_TEXTURE_FIRST + 0) const int kBaseColorTexture = TP_TEXTURE_FROM_MATERIAL;
layout(constant_id = TP_SPEC_MATERIAL_TEXTURE_FIRST + 1) const int kMetallicRoughnessTexture = TP_TEXTURE_FROM_MATERIAL;
layout(constant_id = TP_SPEC_MATERIAL_TEXTURE_FIRST + 2) const int kNormalTexture = TP_TEXTURE_FROM_MATERIAL;
layout(constant_id = TP_SPEC_MATERIAL_TEXTURE_FIRST + 3) const int kOcclusionTexture = TP_TEXTURE_FROM_MATERIAL;
layout(constant_id = TP_SPEC_MATERIAL_TEXTURE_FIRST + 4) const int kEmissiveTexture = TP_TEXTURE_FROM_MATERIAL;
// The slot's index: the compiled-in one, or the buffer's (index).
#define TP_SLOT_INDEX(spec, index) ((spec) == TP_TEXTURE_FROM_MATERIAL ? (index) : (spec))
// sampleTexture() with a compiled-in index: the branches fold away at specialization, and the
// array index is a constant (an in-range one where the branch is dead).
#define TP_SAMPLE_SLOT(spec, index, uv, fallback)                                               \
    ((spec) == TP_TEXTURE_FROM_MATERIAL ? sampleTexture(index, uv, fallback)                    \
     : ((spec) < 0 || (spec) >= kTextureCount)                                                  \
         ? (fallback)                                                                           \
         : TP_MATERIAL_TEXTURE(((spec) >= 0 && (spec) < kTextureCount) ? (spec) : 0, uv))
#else
#define TP_SLOT_INDEX(spec, index) (index)
#define TP_SAMPLE_SLOT(spec, index, uv, fallback) sampleTexture(index, uv, fallback)
#endif

// position/normal/uv/tangent/color: interpolated vertex outputs; frontFacing: gl_FrontFacing.
MaterialSample evalMaterial(MaterialGpu m, vec3 position, vec3 normal, vec2 uv, vec4 tangent,
                            vec4 color, bool frontFacing) {
    MaterialSample r;
    vec4 base = m.baseColorFactor * color * TP_SAMPLE_SLOT(kBaseColorTexture, m.baseColorTexture, uv, vec4(1.0));
    vec4 mr = TP_SAMPLE_SLOT(kMetallicRoughnessTexture, m.metallicRoughnessTexture, uv, vec4(1.0));
    r.alpha = base.a;

    // Degenerate normals (zero length, NaN) fall back to the geometric normal.
    vec3 geomN = normalize(cross(TP_MATERIAL_POSITION_DX(position), TP_MATERIAL_POSITION_DY(position)));
    vec3 n = normal;
    float nl = length(n);
    n = (nl > 1e-8) ? n / nl : geomN;
    if (TP_SLOT_INDEX(kNormalTexture, m.normalTexture) >= 0) {
        vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
        float tl = length(t);
        if (tl > 1e-8) {
            t /= tl;
            vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
            vec3 tn = TP_SAMPLE_SLOT(kNormalTexture, m.normalTexture, uv, vec4(0.5, 0.5, 1.0, 1.0)).xyz * 2.0 - 1.0;
            tn.xy *= m.normalScale;
            vec3 mapped = t * tn.x + b * tn.y + n * tn.z;
            float ml = length(mapped);
            if (ml > 1e-8) n = mapped / ml;
        }
    }
    if (m.doubleSided != 0u && !frontFacing) n = -n;
    if (any(isnan(n))) n = vec3(0.0, 0.0, 1.0);

    r.surface.position = position;
    r.surface.normal = n;
    vec3 toViewer = -position; // camera-relative: the viewer is at the origin
    float vl = length(toViewer);
    r.surface.toViewer = vl > 0.0 ? toViewer / vl : n;
    r.surface.baseColor = base.rgb;
    r.surface.metallic = clamp(m.metallic * mr.b, 0.0, 1.0);
    r.surface.roughness = clamp(m.roughness * mr.g, 0.0, 1.0);
    float ao = TP_SAMPLE_SLOT(kOcclusionTexture, m.occlusionTexture, uv, vec4(1.0)).r;
    r.occlusion = 1.0 + m.occlusionStrength * (ao - 1.0);
    r.emissive = m.emissive * TP_SAMPLE_SLOT(kEmissiveTexture, m.emissiveTexture, uv, vec4(1.0)).rgb;
    return r;
}

// Ambient + emissive: the light-independent part every pipeline adds once.
vec3 ambientAndEmissive(MaterialSample ms) {
    vec3 diffuseColor = ms.surface.baseColor * (1.0 - ms.surface.metallic);
    return frame.ambient.rgb * diffuseColor * ms.occlusion + ms.emissive;
}
#endif
