#pragma once
// The reference's knobs and the typed settings its renderer reads (register.cpp builds the
// schema from the same declarations).
#include "core/renderer/knobs.h"

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
};

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);

} // namespace tp::ref
