#pragma once
// Texture fetches a pass's materials make (docs/efficiency.md, "Placing a pass: what is
// counted"): shaders/include/material.glsl samples each of a material's slots (base colour,
// metal-rough, occlusion, emissive; the normal map only where the tangent is not degenerate, so
// it is not counted) that names a texture of the scene, once per shaded fragment or pixel; an
// absent slot costs no fetch. Which material covers which fragment is not known, so a pass is
// counted at its draws' fewest: a lower bound.
#include <initializer_list>
#include <string>
#include <vector>

#include "core/gpuscene/scene_gpu.h"
#include "core/renderer/renderer.h"
#include "core/scene/scene.h"

namespace tp {

// The textures one fragment of `material` samples.
int materialFetches(const Scene& scene, const Material& material);

// The fewest of any of `draws`' materials: the fetches per fragment a pass drawing them makes
// at the least. 0 without draws.
double minMaterialFetches(const Scene& scene, const std::vector<const DrawItem*>& draws);

// A pass that samples the materials of `filters`' draws once per item of `base` (`share` of
// them: a pass whose other items sample nothing). Every draw of the scene, not only those on
// screen: the fewest over more draws is still a lower bound.
PassOpWork materialFetchWork(const SceneGpu& scene, const std::string& pass,
                             std::initializer_list<DrawFilter> filters, PassLightWork::Base base,
                             double share = 1.0);

} // namespace tp
