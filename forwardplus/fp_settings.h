#pragma once
// Forward+'s knobs and the typed settings its passes read, turned from RenderSettings once in
// the factory (register.cpp builds the schema from the same declarations).
#include <string>

#include "core/lightassign/knobs.h"
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/hdr_knob.h"
#include "core/renderer/knobs.h"
#include "core/renderer/msaa_knob.h"
#include "core/renderer/shadow_raster_knob.h"
#include "forwardplus/forwardplus_shared.h"

namespace tp::fp {

// --light-lists: the values are the shaders' TP_FP_LAYOUT_* (a specialization constant).
enum class ListLayout : uint32_t {
    Compact = TP_FP_LAYOUT_COMPACT,
    Fixed = TP_FP_LAYOUT_FIXED,
    Linked = TP_FP_LAYOUT_LINKED,
};
enum class Spheres { Auto, Pass, Inline };        // --light-spheres
enum class CullBy { Auto, Invocation, Subgroup }; // --cull-by

struct Settings {
    uint32_t width = 0, height = 0;
    Sampling sampling;
    la::AssignSettings assign;
    la::Loop loop = la::Loop::Lane;
    ListLayout lists = ListLayout::Compact;
    uint32_t tileCapacity = 256;
    Spheres spheres = Spheres::Auto;
    CullBy cullBy = CullBy::Auto;
    HdrStorage hdr = HdrStorage::Fp16; // --hdr, resolved: auto is Forward+'s RGBA16F
    CullGeometry cullGeometry = CullGeometry::None; // --cull-geometry
    ShadowRaster shadowRaster = ShadowRaster::Hardware; // --shadow-raster: the atlas's faces
};

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);
// The knob text of a value, for the report's notes ("--light-spheres auto").
const std::string& listsText(ListLayout l);
const std::string& spheresText(Spheres s);

} // namespace tp::fp
