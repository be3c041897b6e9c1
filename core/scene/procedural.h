#pragma once
// Built-in procedural scenes, deterministic. The courtyard stands in for Crytek Sponza:
// a ~30 x 13 x 60 m courtyard with two storeys of colonnades, arches, a gallery floor,
// blended hanging cloth panels, emissive strips and textures generated in code.
#include <cstdint>
#include <string>

#include "core/scene/scene.h"
#include "core/util/result.h"

namespace tp {

struct CourtyardOptions {
    // 1.0 gives about 250,000 triangles; smaller values give test-sized versions
    // (tessellation of columns, arches and cloth scales with it).
    float detail = 1.0f;
};

Scene makeCourtyard(const CourtyardOptions& options = {});

// Looks up a built-in scene by name ("courtyard", "courtyard-small"); error lists the names.
Result<Scene> makeBuiltinScene(const std::string& name);

} // namespace tp
