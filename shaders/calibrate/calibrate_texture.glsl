// The fetch loop of calibrate's texture ceilings: `steps` bilinear fetches of the RGBA8 texture
// (TP_CAL_TEXTURE_SIZE squared, one mip level, the size of the courtyard's material textures).
// Neighbouring invocations or pixels fetch neighbouring texels, each step a new place, between
// texel centres (four texels blended). Compute fetches level 0 explicitly; a fragment shader
// uses texture() with its derivatives (one texel per pixel: level 0), as a material does.
#ifndef TP_CALIBRATE_TEXTURE_GLSL
#define TP_CALIBRATE_TEXTURE_GLSL

layout(set = 1, binding = TP_CAL_BINDING_TEXTURE) uniform sampler2D calTexture;

vec4 textureFetches(vec2 texel, uint steps) {
    const float inv = 1.0 / float(TP_CAL_TEXTURE_SIZE);
    vec4 sum = vec4(0.0);
    for (uint k = 0u; k < steps; ++k) {
        const vec2 uv = (texel + vec2(float((k * 37u) & 1023u), float((k * 11u) & 1023u)) + 0.25) * inv;
#ifdef TP_CAL_FRAGMENT
        sum += texture(calTexture, uv);
#else
        sum += textureLod(calTexture, uv, 0.0);
#endif
    }
    return sum;
}

// The texture read as an image: `steps` texelFetch (one texel, no filtering), neighbouring
// invocations on neighbouring texels, the steps over a 16x16-texel window, as a culling pass
// reads its tile's depth: the fastest way a pass reads an image (an upper bound; a far step
// each time measured lavapipe 25 % slower than its light culling read). 4 MiB in all: it may
// stay in a GPU's last-level cache, as an image the previous pass wrote may.
vec4 texelReads(ivec2 texel, uint steps) {
    vec4 sum = vec4(0.0);
    for (uint k = 0u; k < steps; ++k)
        sum += texelFetch(calTexture, (texel + ivec2(k & 15u, (k >> 4u) & 15u)) & (TP_CAL_TEXTURE_SIZE - 1), 0);
    return sum;
}

#ifndef TP_CAL_FRAGMENT
// texelReads over the 4x multisampled depth: each step a texel's four samples, one texelFetch
// each, as tile_depth_bounds and the light culling read a multisampled depth (16 MiB in all).
// On lavapipe a pass read its 4x depth faster than image_read's single samples (docs/efficiency.md).
layout(set = 1, binding = TP_CAL_BINDING_DEPTH_MSAA4) uniform sampler2DMS calDepthMsaa4;

float sampleReads(ivec2 texel, uint steps) {
    float sum = 0.0;
    for (uint k = 0u; k < steps; ++k) {
        const ivec2 t = (texel + ivec2(k & 15u, (k >> 4u) & 15u)) & (TP_CAL_TEXTURE_SIZE - 1);
        for (int s = 0; s < 4; ++s) sum += texelFetch(calDepthMsaa4, t, s).r;
    }
    return sum;
}
#endif
#endif
