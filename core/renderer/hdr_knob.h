#pragma once
// The storage precision of a pipeline's radiance target (`--hdr auto|fp32|fp16`), shared by
// Forward+ (its forward shading's colour targets) and the pipelines that compose
// core/passes/tiled_lighting (deferred, the visibility buffer): one declaration, so all read
// one option with one meaning. Their own storage differs (Forward+ RGBA16F, the compute
// pipelines RGBA32F), and a knob several renderers declare has one default (knobs.h): hence
// `auto`, each pipeline's own storage, resolved in its typed settings by readHdr().
#include <string>

#include "core/renderer/knobs.h"

namespace tp {

enum class HdrStorage { Fp32, Fp16 };
const Knob& hdrKnob();
// The storage --hdr gives a pipeline whose own storage is `own` (what `auto` means there).
HdrStorage readHdr(const RenderSettings& s, HdrStorage own);
// "fp32" or "fp16", for a report's notes.
const char* hdrText(HdrStorage h);

} // namespace tp
