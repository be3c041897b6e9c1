#pragma once
// The storage precision of the radiance a tiled compute lighting pass writes (`--hdr
// fp32|fp16`), shared by the pipelines that compose core/passes/tiled_lighting (deferred, the
// visibility buffer): one declaration, so both read one option with one meaning.
#include "core/render/knobs.h"

namespace tp {

enum class HdrStorage { Fp32, Fp16 };
const ChoiceKnob<HdrStorage>& hdrKnob();

} // namespace tp
