// The standard MSAA sample locations of the Vulkan spec ("Multisampling", table "Standard
// sample locations"), pixel-relative, y down (framebuffer coordinates), each written V(x, y)
// for the includer's vector constructor: read by the GPU's surface readers
// (sample_locations.glsl, V = vec2) and by the CPU error models (core/camera/pixel_position.h:
// standardSampleOffset, V = glm::dvec2), so the two never disagree.
#ifndef TP_SAMPLE_LOCATIONS_H
#define TP_SAMPLE_LOCATIONS_H
#define TP_SAMPLE_LOCATIONS_2(V) V(0.75, 0.75), V(0.25, 0.25)
#define TP_SAMPLE_LOCATIONS_4(V) V(0.375, 0.125), V(0.875, 0.375), V(0.125, 0.625), V(0.625, 0.875)
#define TP_SAMPLE_LOCATIONS_8(V)                                                                \
    V(0.5625, 0.3125), V(0.4375, 0.6875), V(0.8125, 0.5625), V(0.3125, 0.1875),                 \
        V(0.1875, 0.8125), V(0.0625, 0.4375), V(0.6875, 0.9375), V(0.9375, 0.0625)
#endif
