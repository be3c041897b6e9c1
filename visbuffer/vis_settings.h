#pragma once
// The visibility buffer's knobs and the typed settings its passes read, turned from
// RenderSettings once in the factory (register.cpp builds the schema from the same
// declarations). Every knob is a library knob: the light assignment's, the MSAA shading rate
// and the tiled lighting's radiance precision.
#include "core/lightassign/knobs.h"
#include "core/render/hdr_knob.h"
#include "core/render/knobs.h"
#include "core/render/msaa_knob.h"

namespace tp::vis {

struct Settings {
    uint32_t width = 0, height = 0;
    Sampling sampling;
    bool debug = false;
    la::AssignSettings assign;
    HdrStorage hdr = HdrStorage::Fp32;
};

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);

} // namespace tp::vis
