// The standard MSAA sample locations, shared by the surface readers of the tiled lighting
// pass (deferred/gbuffer_read.glsl, visbuffer/vis_read.glsl). The includer declares
// kSamples (TP_SPEC_SAMPLES).
#ifndef TP_SAMPLE_LOCATIONS_GLSL
#define TP_SAMPLE_LOCATIONS_GLSL
// Sample locations, pixel-relative, y down (framebuffer coordinates, as the compute pixel
// grid and gl_FragCoord): the standard locations of the Vulkan spec ("Multisampling",
// table "Standard sample locations"), which the device uses when
// VkPhysicalDeviceLimits::standardSampleLocations is true (otherwise the renderer reports
// under left-out that edge samples are reconstructed at assumed positions).
vec2 sampleOffset(uint s) {
    if (kSamples == 2u) return s == 0u ? vec2(0.75, 0.75) : vec2(0.25, 0.25);
    if (kSamples == 4u) {
        const vec2 p4[4] = vec2[](vec2(0.375, 0.125), vec2(0.875, 0.375), vec2(0.125, 0.625),
                                  vec2(0.625, 0.875));
        return p4[s & 3u];
    }
    if (kSamples == 8u) {
        const vec2 p8[8] = vec2[](vec2(0.5625, 0.3125), vec2(0.4375, 0.6875), vec2(0.8125, 0.5625),
                                  vec2(0.3125, 0.1875), vec2(0.1875, 0.8125), vec2(0.0625, 0.4375),
                                  vec2(0.6875, 0.9375), vec2(0.9375, 0.0625));
        return p8[s & 7u];
    }
    return vec2(0.5);
}

#endif
