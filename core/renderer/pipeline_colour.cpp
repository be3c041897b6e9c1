#include "core/renderer/pipeline_colour.h"

#include <cstdio>
#include <iterator>

#include "core/renderer/renderer.h"

namespace tp {
namespace {

const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                          "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

} // namespace

int pipelineColour(const std::string& name) {
    const std::vector<RendererEntry>& all = registeredRenderers();
    for (size_t i = 0; i < all.size(); ++i)
        if (all[i].name == name) return int(i);
    return -1;
}

const char* paletteHex(int index) {
    // -1 (a name nothing registered) wraps to the last entry, as the pages always drew it.
    return kPalette[size_t(index) % std::size(kPalette)];
}

std::array<uint8_t, 3> paletteRgb(int index) {
    unsigned r = 0, g = 0, b = 0;
    std::sscanf(paletteHex(index), "#%2x%2x%2x", &r, &g, &b);
    return {uint8_t(r), uint8_t(g), uint8_t(b)};
}

} // namespace tp
