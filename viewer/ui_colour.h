#pragma once
// A pipeline's colour in the viewer's panels: the one report.html, sweep.html and stress.html
// draw it in (core/renderer/pipeline_colour.h).
#include <string>

#include <imgui.h>

#include "core/renderer/pipeline_colour.h"

namespace tp::view {

inline ImVec4 pipelineImColour(const std::string& name) {
    const std::array<uint8_t, 3> c = paletteRgb(pipelineColour(name));
    return ImVec4(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1.0f);
}

// A small square of the pipeline's colour, then the next item on the same line.
inline void pipelineSwatch(const std::string& name) {
    ImGui::ColorButton(("##swatch" + name).c_str(), pipelineImColour(name),
                       ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                       ImVec2(ImGui::GetTextLineHeight(), ImGui::GetTextLineHeight()));
    ImGui::SameLine();
}

} // namespace tp::view
