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

// position/normal/uv/tangent/color: interpolated vertex outputs; frontFacing: gl_FrontFacing.
MaterialSample evalMaterial(MaterialGpu m, vec3 position, vec3 normal, vec2 uv, vec4 tangent,
                            vec4 color, bool frontFacing) {
    MaterialSample r;
    vec4 base = m.baseColorFactor * color * sampleTexture(m.baseColorTexture, uv, vec4(1.0));
    vec4 mr = sampleTexture(m.metallicRoughnessTexture, uv, vec4(1.0));
    r.alpha = base.a;

    // Degenerate normals (zero length, NaN) fall back to the geometric normal.
    vec3 geomN = normalize(cross(TP_MATERIAL_POSITION_DX(position), TP_MATERIAL_POSITION_DY(position)));
    vec3 n = normal;
    float nl = length(n);
    n = (nl > 1e-8) ? n / nl : geomN;
    if (m.normalTexture >= 0) {
        vec3 t = tangent.xyz - n * dot(n, tangent.xyz);
        float tl = length(t);
        if (tl > 1e-8) {
            t /= tl;
            vec3 b = cross(n, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
            vec3 tn = sampleTexture(m.normalTexture, uv, vec4(0.5, 0.5, 1.0, 1.0)).xyz * 2.0 - 1.0;
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
    float ao = sampleTexture(m.occlusionTexture, uv, vec4(1.0)).r;
    r.occlusion = 1.0 + m.occlusionStrength * (ao - 1.0);
    r.emissive = m.emissive * sampleTexture(m.emissiveTexture, uv, vec4(1.0)).rgb;
    return r;
}

// Ambient + emissive: the light-independent part every pipeline adds once.
vec3 ambientAndEmissive(MaterialSample ms) {
    vec3 diffuseColor = ms.surface.baseColor * (1.0 - ms.surface.metallic);
    return frame.ambient.rgb * diffuseColor * ms.occlusion + ms.emissive;
}
#endif
