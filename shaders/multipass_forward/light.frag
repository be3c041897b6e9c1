#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require // TP_MP_LIGHT_PASS's count
#extension GL_KHR_shader_subgroup_arithmetic : require
// One light's contribution, added into the accumulation target. Opaque and masked surfaces:
// blend ONE + ONE, alpha kept. Blended surfaces return (alpha * light, alpha) and blend
// "under" (colour: DST_ALPHA, ONE; alpha: ZERO, ONE_MINUS_SRC_ALPHA) with their triangles
// in reverse order: the target's alpha carries the transmittance of the nearer layers of
// the same draw, so after all passes a blended draw holds exactly what shading all lights
// at once and blending once gives (blended_pass.cpp, docs/multipass_forward.md).
//
// Opaque and masked draws (the light passes): a 2x2 quad beyond the light's range leaves
// early with the zero it adds (docs/multipass_forward.md, "Quads beyond a light's range").
// TP_MP_LIGHT_PASS (the light passes' own variants): the fragments that evaluate their light
// are counted (multipass_shared.h: TP_MP_BINDING_LIT).
//
// TP_MP_BLENDED_GPU (mp_light_blend_frag): the blended light draws and their transmittance
// resets as one pipeline, drawn by indirect commands that blended_light_draws.comp wrote. The
// command's firstInstance (scene_material_vert, flat) names the light's slot and whether this is
// the reset; the material is the draw's own (DrawPush). Dual-source blending, colour
// src0 * DST_ALPHA + dst and alpha src0.a + dst.a * (1 - src1.a): a light draw gives src0 =
// (a * light, 0) and src1.a = a, the same sums as the "under" blend above; a reset gives
// src0 = (-0, -0, -0, 1) and src1.a = 1: alpha 1 + T * 0 = 1, colour dst + (-0) * T = dst
// exactly (-0, not +0, so that a -0 stays -0), what the alpha-only reset draw wrote. The light's
// scissor, which a command cannot set, is a discard outside the light's rectangle (its row).
#include "include/shared.h"
#include "multipass_forward/multipass_shared.h"
#include "include/scene_bindings.glsl"
#include "include/material.glsl"
#include "include/scene_inputs.glsl"
#include "include/shadow_light.glsl"

#ifdef TP_MP_BLENDED_GPU
#include "multipass_forward/blended_light_draws.h"
layout(location = TP_LOCATION_MATERIAL) flat in uint inLightWord; // firstInstance
layout(std430, set = TP_SET_PASS, binding = TP_MPBL_BINDING_LIGHTS) readonly buffer LightRowBlock {
    LightDrawLight lightRows[];
};
layout(location = 0, index = 0) out vec4 outColor;
layout(location = 0, index = 1) out vec4 outWeight; // src1: its alpha is the layer's alpha

bool inRect(ivec2 lo, ivec2 hi, ivec4 r) {
    return lo.x < r.z && r.x < hi.x && lo.y < r.w && r.y < hi.y;
}
#else
layout(location = 0) out vec4 outColor;
#endif

#ifdef TP_MP_LIGHT_PASS
// The count is a side effect: without early tests a fragment that fails depth EQUAL or the
// stencil could run the shader first and be counted (and an NVIDIA GPU then tests late, for
// every fragment). Early tests change nothing else here: no discard, no depth write, and the
// stencil's light tag is written by the test itself.
layout(early_fragment_tests) in;
// Only a GPU draws these variants (multipass_forward/light_count.h): lavapipe (Mesa 22.3)
// cannot compile gl_HelperInvocation, and their storage buffer alone made its light passes
// slower (1,075 -> 1,300 ms, docs/multipass_forward.md); it draws with the plain variants.
layout(std430, set = TP_SET_PASS, binding = TP_MP_BINDING_LIT) buffer LitBlock {
    uint lit[TP_MP_LIT_SLOTS];
};

// One add per subgroup of the fragments (not helpers) that evaluate their light.
void countLit() {
    if (gl_HelperInvocation) return;
    const uint n = subgroupAdd(1u);
    if (subgroupElect()) {
        const uvec2 p = uvec2(gl_FragCoord.xy);
        atomicAdd(lit[(p.x / 8u + p.y / 8u * 5u) % TP_MP_LIT_SLOTS], n);
    }
}
#endif

#ifndef TP_MP_BLENDED_GPU
// Whether no fragment of this 2x2 quad lies within the light's range, by a margin (this test
// need not round as evalLight's does): the quad then adds exactly the zero evalLight gives
// there, and may skip the material. The derivatives run in uniform control flow: each lane's
// flag OR-ed with its row neighbour's (fine x), then with its column neighbour's (fine y).
bool quadOutOfRange(LightGpu light) {
    if (light.type == TP_LIGHT_DIRECTIONAL) return false;
    const vec3 position = TP_INPUT(inPosition) * (1.0 / TP_INPUT(inOne));
    const float reach = length(light.position - position) < light.range * 1.0001 ? 1.0 : 0.0;
    const float pair = dFdxFine(reach) != 0.0 ? 1.0 : reach;
    const float quad = dFdyFine(pair) != 0.0 ? 1.0 : pair;
    return quad == 0.0;
}
#endif

void main() {
#ifdef TP_MP_BLENDED_GPU
    const LightDrawLight row = lightRows[inLightWord & TP_MPBL_SLOT_MASK];
    // The scissor's pixels (framebuffer coordinates, as the scissor). A 2x2 quad with no pixel
    // in the rectangle leaves at once (no pixel of it needs another's derivatives); any other
    // fragment outside it shades first, so its quad's derivatives are those a scissored draw's
    // helper invocations give, and is discarded after.
    const ivec2 pixel = ivec2(floor(gl_FragCoord.xy)), quad = pixel & ~1;
    if (!inRect(quad, quad + 2, row.rect)) discard;
    const bool inside = inRect(pixel, pixel + 1, row.rect);
    if ((inLightWord & TP_MPBL_RESET) != 0u) {
        if (!inside) discard;
        outColor = vec4(-0.0, -0.0, -0.0, 1.0);
        outWeight = vec4(1.0);
        return;
    }
    const uint light = row.light;
#else
    const uint light = draw.TP_MP_LIGHT_INDEX;
    // The light passes' opaque and masked draws (the blended ones need their alpha).
    if (kAlphaMode != TP_ALPHA_BLEND && quadOutOfRange(lights[light])) {
        outColor = vec4(0.0); // what evalLight's zero gives below, without the material
        return;
    }
#ifdef TP_MP_LIGHT_PASS
    countLit();
#endif
#endif
    MaterialSample ms = evalFragmentMaterial();
    // The _shadow twin (--shadows) multiplies by the map this pass rendered for the light
    // (one light's map: TP_SPEC_SHADOW_LOCAL); the plain shader is evalLight() itself.
    vec3 c = evalLightShadowed(lights[light], ms.surface);
#ifdef TP_MP_BLENDED_GPU
    outColor = vec4(c * ms.alpha, 0.0);
    outWeight = vec4(ms.alpha);
    if (!inside) discard;
#else
    if (kAlphaMode == TP_ALPHA_BLEND)
        outColor = vec4(c * ms.alpha, ms.alpha);
    else
        outColor = vec4(c, 0.0); // the blend state keeps the destination's alpha
#endif
}
