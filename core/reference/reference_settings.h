#pragma once
// The reference's knobs and the typed settings its renderer reads (register.cpp builds the
// schema from the same declarations).
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/knobs.h"
#include "core/renderer/shadow_raster_knob.h"

namespace tp::ref {

enum class Precision { Fp64, Fp32 };         // --reference-precision
enum class MsaaMode { Sample, Center };      // --reference-msaa
enum class Position { Interpolated, Depth }; // --reference-position
enum class Shadows { Rays, Maps };            // --reference-shadows

struct Settings {
    Precision precision = Precision::Fp64;
    MsaaMode msaa = MsaaMode::Sample;
    Position position = Position::Interpolated;
    Shadows shadows = Shadows::Rays;
    // --reference-shadows maps: the maps rasterized as the pipelines' are (their
    // --shadow-raster, and under compute their --cull-geometry's face cull, which it needs),
    // read from the pipelines' knobs: a texel the two rasterizers store differently would
    // otherwise count as the pipeline's error (docs/shadows.md). The geometry is drawn whole
    // either way.
    ShadowRaster mapsRaster = ShadowRaster::Hardware;
    CullGeometry mapsCull = CullGeometry::None;
};

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);
// What the reference's image takes from the pipelines' settings, as lines of text (empty when
// nothing: no shadows, or shadow rays): the maps' rasterizer under --reference-shadows maps.
// The reference cache's key holds it.
std::string followedSettingsText(const RenderSettings& s);

} // namespace tp::ref
