#pragma once
// Every knob a run has, in one place, with a one-line comment each. The CLI exposes them
// (see --help) and report.json records them.
#include <cstdint>
#include <string>

namespace tp {

struct RenderSettings {
    uint32_t width = 320;          // output resolution
    uint32_t height = 180;
    uint32_t msaa = 1;             // samples per pixel: 1, 2, 4, 8 (as the device supports)
    bool referenceFp64 = true;     // reference accumulates the light sum in fp64 when the device can
    // Reference under MSAA: "sample" shades every sample at its own location (supersampling,
    // the ground truth); "center" shades every covered sample with the inputs at the pixel
    // centre, the once-per-pixel shading an MSAA pipeline approximates (tests split a
    // pipeline's error into its shading rate and the rest with it).
    std::string referenceMsaaShading = "sample";
    uint32_t tileSize = 16;        // tiled pipelines: tile edge in pixels (8, 16, 32)
    // Forward+ light-list layout: "compact" (count, prefix sum, fill: never drops a light),
    // "fixed" (flat fixed capacity per tile, AMD ForwardPlus11; drops are counted),
    // "linked" (per-tile linked lists with a head buffer).
    std::string lightLists = "compact";
    uint32_t tileCapacity = 256;   // "fixed" layout: light slots per tile
    std::string gbuffer = "compact";         // deferred G-buffer: "compact" or "wide" (fp32)
    // Deferred G-buffer under MSAA: "pixel" evaluates the material once per pixel and writes
    // it to every covered sample (Lauritzen 2010: samples of one surface compare equal, so
    // only edges are lit per sample); "sample" evaluates it at every sample and lights every
    // sample (supersampled deferred: the supersampled reference's image, at its cost).
    std::string gbufferMsaa = "pixel";
    std::string deferredLighting = "tiled";  // deferred lighting: "tiled" or "volumes"
    std::string accum = "fp32";              // multipass forward accumulation: "fp16" or "fp32"
    bool debug = false;            // renderers export their debug images (heat maps, ...)
};

} // namespace tp
