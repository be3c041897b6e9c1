#pragma once
// The visibility-buffer pipeline ("visbuffer", Burns and Hunt 2013): a visibility pass writes
// depth and a packed (draw, triangle) id per sample; the tiled lighting pass of the library
// resolves in compute with the visibility reader (shaders/visbuffer/vis_read.glsl): it
// fetches each id's triangle, rebuilds barycentrics and their derivatives analytically,
// evaluates the material and lights it from the tile's or cluster's lights. Blended
// materials take the library's hybrid forward path (core/passes/hybrid_blended.h).
// Publishes "hdr" (--hdr as deferred's) and "depth" (D32, MSAA: sample 0). docs/visbuffer.md.
#include <memory>

#include "core/renderer/renderer.h"

namespace tp {

std::unique_ptr<Renderer> createVisbufferRenderer(const RendererCreateInfo& info);

} // namespace tp
