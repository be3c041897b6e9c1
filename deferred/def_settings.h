#pragma once
// Deferred's knobs and the typed settings its passes read, turned from RenderSettings once in
// the factory (register.cpp builds the schema from the same declarations).
#include "core/lightassign/knobs.h"
#include "core/renderer/cull_geometry_knob.h"
#include "core/renderer/hdr_knob.h"
#include "core/renderer/knobs.h"
#include "core/renderer/msaa_knob.h"
#include "core/renderer/shadow_raster_knob.h"

namespace tp {
class GpuContext;
}

namespace tp::def {

enum class GBuffer { Compact, Wide };   // --gbuffer
enum class Lighting { Tiled, Volumes }; // --deferred-lighting
enum class Prepass { Auto, On, Off };   // --gbuffer-prepass
using Hdr = HdrStorage;                 // --hdr (core/renderer/hdr_knob.h)

struct Settings {
    uint32_t width = 0, height = 0;
    Sampling sampling;
    bool debug = false;
    bool manyViews = false; // RenderSettings::manyViews: per-view lists get headroom
    la::AssignSettings assign;
    la::TileGroup tileGroup = la::TileGroup::Auto; // --tile-group
    GBuffer gbuffer = GBuffer::Compact;
    Prepass prepass = Prepass::Auto;
    Lighting lighting = Lighting::Tiled;
    Hdr hdr = Hdr::Fp32;
    CullGeometry cullGeometry = CullGeometry::None; // --cull-geometry: the G-buffer pass
    ShadowRaster shadowRaster = ShadowRaster::Hardware; // --shadow-raster: the atlas's faces
};

KnobSchema knobs();
Settings readSettings(const RenderSettings& s);
// --gbuffer-prepass resolved: auto is on for a GPU under MSAA, off at 1x and on a CPU device
// (docs/deferred.md, "The depth prepass": where it measured faster).
bool prepassOn(const GpuContext& ctx, const Settings& s);

} // namespace tp::def
