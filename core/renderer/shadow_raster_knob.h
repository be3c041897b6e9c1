#pragma once
// `--shadow-raster hardware|compute`: who rasterizes the shadow maps' faces (docs/shadows.md,
// "Rasterizing the maps in compute"). hardware (the default: the images of a build without
// the option, bit for bit): the graphics pipeline, one indirect draw per (face, draw). compute:
// compute shaders from the culled meshlets (core/passes/shadow_raster.h), the depth kept in a
// buffer with a 32-bit atomic max per texel and copied into the same D32 map, so every
// sampling shader is unchanged. Needs --cull-geometry frustum|full (it rasterizes the cull's
// rows) and the atlas residency (one light's map, deferred's volumes and multipass forward,
// stays with the hardware: refused with one line). Declared here, once, for every pipeline
// that renders shadow maps (Forward+, deferred, the visibility buffer, multipass forward).
#include "core/renderer/knobs.h"

namespace tp {

enum class ShadowRaster { Hardware, Compute };
const ChoiceKnob<ShadowRaster>& shadowRasterKnob();

} // namespace tp
