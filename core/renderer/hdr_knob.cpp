#include "core/renderer/hdr_knob.h"

namespace tp {
namespace {

enum class HdrChoice { Auto, Fp32, Fp16 };

const ChoiceKnob<HdrChoice>& choiceKnob() {
    static const ChoiceKnob<HdrChoice> k{
        "hdr",
        {{HdrChoice::Auto, "auto"}, {HdrChoice::Fp32, "fp32"}, {HdrChoice::Fp16, "fp16"}},
        "Radiance target (hdr, hdr_msaa) of Forward+, deferred and visbuffer: fp32 (RGBA32F, the "
        "light sum exact to readback), fp16 (RGBA16F: half the bytes, one fp16 rounding per "
        "store, saturating at 65,504) or auto (each pipeline's own: fp16 for Forward+, fp32 for "
        "deferred and visbuffer; counter hdr_storage_bits_per_channel says which)"};
    return k;
}

} // namespace

const Knob& hdrKnob() {
    return choiceKnob().knob();
}

HdrStorage readHdr(const RenderSettings& s, HdrStorage own) {
    switch (choiceKnob().in(s)) {
    case HdrChoice::Fp32:
        return HdrStorage::Fp32;
    case HdrChoice::Fp16:
        return HdrStorage::Fp16;
    case HdrChoice::Auto:
        break;
    }
    return own;
}

const char* hdrText(HdrStorage h) {
    return h == HdrStorage::Fp16 ? "fp16" : "fp32";
}

} // namespace tp
