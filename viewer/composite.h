#pragma once
// The scene area of the viewer, composed on the CPU from the renderers' read-back images: the
// split view (A left of the divider, B right), flip (A and B swapped), the difference heat map
// (|A - B| on compare's scale rule, with its legend) and the debug overlays. The same images
// and functions compare uses (tonemap, signedDifference, heatMap), so what the viewer shows is
// what the report would.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/image/image.h"
#include "viewer/view_state.h"

namespace tp::view {

// The divider's colour: amber, a colour the tonemapped scene and the heat maps rarely hold
// exactly, so a test (and a person) can find the line.
inline constexpr uint8_t kDividerRgb[3] = {255, 176, 0};
inline constexpr uint32_t kLegendHeight = 24;

struct CompositeInput {
    const ImageRGBA* a = nullptr; // linear HDR, null until rendered
    const ImageRGBA* b = nullptr;
    const ImageRGBA* overlay = nullptr; // display-space debug image (any size: scaled)
    DisplayMode mode = DisplayMode::Split;
    float split = 0.5f;
    bool flip = false;
    float exposureEv = 0.0f;
};

struct Composite {
    uint32_t width = 0, height = 0; // height includes the legend in Difference mode
    std::vector<uint8_t> rgba;      // 8-bit display values, row 0 at the top
    float diffScale = 0;            // the heat map's upper end (Difference mode)
    std::string note;               // what is missing ("B not rendered yet")
    // Composed on the GPU (gpu_composite.h): `rgba` is empty, the bytes are in this buffer on
    // the UI's device, already in the target's channel order.
    VkBuffer gpuBytes = VK_NULL_HANDLE;
};

Composite compose(const CompositeInput& in, uint32_t width, uint32_t height);
// The divider's column for a split share (what compose draws and the mouse drags).
uint32_t dividerColumn(float split, uint32_t width);

} // namespace tp::view
