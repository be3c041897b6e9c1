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
    uint32_t tileSize = 16;        // tiled pipelines: tile edge in pixels (8, 16, 32)
};

} // namespace tp
