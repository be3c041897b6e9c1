// The standard MSAA sample locations, shared by the surface readers of the tiled lighting
// pass (deferred/gbuffer_read.glsl, visbuffer/vis_read.glsl). The includer declares
// kSamples (TP_SPEC_SAMPLES).
#ifndef TP_SAMPLE_LOCATIONS_GLSL
#define TP_SAMPLE_LOCATIONS_GLSL
#include "include/sample_locations.h"
// Sample locations, pixel-relative, y down (framebuffer coordinates, as the compute pixel
// grid and gl_FragCoord): the standard locations of the Vulkan spec ("Multisampling",
// table "Standard sample locations"), which the device uses when
// VkPhysicalDeviceLimits::standardSampleLocations is true (otherwise the renderer reports
// under left-out that edge samples are reconstructed at assumed positions).
vec2 sampleOffset(uint s) {
    // TP_SAMPLE_LOCATIONS_2, written as the ternary it has always compiled to (an array would
    // change the SPIR-V of every pipeline that reads it).
    if (kSamples == 2u) return s == 0u ? vec2(0.75, 0.75) : vec2(0.25, 0.25);
    if (kSamples == 4u) {
        const vec2 p4[4] = vec2[](TP_SAMPLE_LOCATIONS_4(vec2));
        return p4[s & 3u];
    }
    if (kSamples == 8u) {
        const vec2 p8[8] = vec2[](TP_SAMPLE_LOCATIONS_8(vec2));
        return p8[s & 7u];
    }
    return vec2(0.5);
}

#endif
