// G-buffer deferred as the rest of the program sees it: its name, its knobs, its precision
// model for `triptych stress` (deferred/error_model.cpp).
#include "core/lightassign/assign_knob.h"
#include "core/lightassign/bin_knob.h"
#include "core/lightassign/cull_knob.h"
#include "core/lightassign/tile_knob.h"
#include "core/render/msaa_knob.h"
#include "core/render/renderer.h"
#include "deferred/deferred_renderer.h"
#include "deferred/error_model.h"
#include "deferred/deferred_shared.h"

namespace tp {
namespace {

KnobSchema deferredKnobs() {
    return {la::tileSizeKnob(),
            la::lightCullKnob(),
            la::lightBinKnob(),
            la::lightAssignKnob(),
            la::slicesKnob(),
            Knob::choice("gbuffer", {"compact", "wide"}, "Deferred G-buffer layout: compact (8/16-bit) or wide (fp32)"),
            msaaShadingKnob(), // pixel: Lauritzen 2010 edges; sample: supersampled deferred
            Knob::choice("deferred-lighting", {"tiled", "volumes"},
                         "Deferred lighting: tiled (compute, per-tile lists) or volumes (one draw per light)"),
            Knob::choice("hdr", {"fp32", "fp16"},
                         "Deferred hdr (and hdr_msaa) target: fp32 (RGBA32F, the light sum exact to readback) or "
                         "fp16 (RGBA16F as Forward+'s: half the bytes, one fp16 rounding per store)")};
}

std::vector<stress::CounterAtLeast> deferredStressed(const ErrorModelInput& in) {
    const stress::StressCase& c = in.stressCase;
    if (in.settings.text("deferred-lighting") != "tiled" || c.lightsInOneTile <= TP_DEF_TILE_LIGHT_CAPACITY) return {};
    return {{"tiles_over_shared_capacity", 1, "the 4,096-light shared list must overflow (the case puts " +
                                                  std::to_string(c.lightsInOneTile) + " in one tile)"}};
}

const RendererRegistration registration{
    {"deferred", "G-buffer deferred: tiled compute lighting, hybrid forward pass for blended", createDeferredRenderer,
     20, deferredKnobs(), deferredErrorModel, deferredStressed}};

} // namespace
} // namespace tp
