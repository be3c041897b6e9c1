#include "core/render/hdr_knob.h"

namespace tp {

const ChoiceKnob<HdrStorage>& hdrKnob() {
    static const ChoiceKnob<HdrStorage> k{
        "hdr",
        {{HdrStorage::Fp32, "fp32"}, {HdrStorage::Fp16, "fp16"}},
        "Radiance target (hdr, hdr_msaa) of tiled compute lighting (deferred, visbuffer): fp32 "
        "(RGBA32F, the light sum exact to "
        "readback) or fp16 (RGBA16F as Forward+'s: half the bytes, one fp16 rounding per "
        "store)"};
    return k;
}

} // namespace tp
