#pragma once
// One colour per renderer everywhere a pipeline is drawn (report.html, sweep.html,
// stress.html, the viewer): its place in the registry's order picks an entry of one small
// palette that reads on white and in greyscale, so adding a pipeline never recolours another.
#include <array>
#include <cstdint>
#include <string>

namespace tp {

// The palette index of a pipeline (or the reference); -1 for a name nothing registered.
int pipelineColour(const std::string& name);

// Entry `index` of the palette ("#rrggbb"), wrapping past its end.
const char* paletteHex(int index);

// The same entry as 8-bit red, green and blue (the viewer's ImGui colours).
std::array<uint8_t, 3> paletteRgb(int index);

} // namespace tp
