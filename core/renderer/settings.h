#pragma once
// What a run is given: the view (resolution, MSAA, debug outputs) that every renderer reads,
// and the pipeline knobs, which each renderer declares in its own schema (core/renderer/knobs.h)
// and reads by name. The CLI, sweep and reports are built from those schemas; this
// file knows no pipeline.
#include <cstdint>
#include <map>
#include <string>

#include "core/scene/shadow_settings.h"

namespace tp {

struct RenderSettings {
    uint32_t width = 320; // output resolution
    uint32_t height = 180;
    uint32_t msaa = 1;  // samples per pixel: 1, 2, 4, 8 (as the device supports)
    bool debug = false; // renderers export their debug images (heat maps, ...)
    // Planned to render many views (a camera path, the viewer; core/runner/render_session.h):
    // lists sized from the first view get headroom (each renderer documents how much), and a
    // view that outgrows it is planned again, counted (view_replans). false: sized exactly for
    // the one view, as a single render always was.
    bool manyViews = false;
    ShadowSettings shadows; // default: none (the images of a run without shadows)
    // --pass-statistics: every recorded pass is bracketed by a pipeline-statistics query (its
    // primitive and fragment counts: the work counts and the efficiency need them). false: none
    // are recorded, so a timing run does not pay for them; the report says they are off.
    bool passStatistics = true;
    // Needs a previous plan of the same renderer measured and outgrew (Renderer contract step
    // 7, RendererSession): by the renderer's own names; empty for a first plan.
    std::map<std::string, uint64_t> capacities;
    // Knob values as text, by knob name ("tile" -> "16"). A renderer is built only after its
    // schema has checked them and filled in its defaults (resolveKnobs), so a knob it declared
    // is always here; values of other renderers' knobs are carried along untouched.
    std::map<std::string, std::string> knobs;

    // The value of a declared knob; RendererError if it is missing (a renderer reading a knob
    // it did not declare) or, for integer(), not a whole number.
    const std::string& text(const std::string& name) const;
    uint32_t integer(const std::string& name) const;
    RenderSettings& set(const std::string& name, const std::string& value);
    RenderSettings& set(const std::string& name, uint32_t value);
};

} // namespace tp
