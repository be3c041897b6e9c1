#include "visbuffer/vis_settings.h"

namespace tp::vis {

KnobSchema knobs() {
    return {la::tileSizeKnob().knob(), la::lightCullKnob().knob(),
            la::lightBinKnob().knob(), la::lightAssignKnob().knob(),
            la::slicesKnob().knob(),
            msaaShadingKnob().knob(), // pixel: once per pixel and triangle; sample: every sample
            hdrKnob().knob()};
}

Settings readSettings(const RenderSettings& s) {
    Settings v;
    v.width = s.width;
    v.height = s.height;
    v.sampling = readSampling(s);
    v.debug = s.debug;
    v.assign = la::readAssignSettings(s);
    v.hdr = hdrKnob().in(s);
    return v;
}

} // namespace tp::vis
