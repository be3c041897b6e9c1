#include "core/gpuscene/shadow_plan.h"

#include <cstring>

namespace tp {

uint64_t ShadowPlan::faceTexels() const {
    uint64_t t = 0;
    for (const gpu::ShadowFace& f : faces) t += uint64_t(f.atlas.z) * f.atlas.z;
    return t;
}

bool ShadowPlan::operator==(const ShadowPlan& o) const {
    if (lights.size() != o.lights.size() || faces.size() != o.faces.size()) return false;
    for (size_t i = 0; i < lights.size(); ++i)
        if (lights[i].light != o.lights[i].light || lights[i].edge != o.lights[i].edge) return false;
    return atlasWidth == o.atlasWidth && atlasHeight == o.atlasHeight &&
           localWidth == o.localWidth && localHeight == o.localHeight;
}

bool ShadowPlan::sameUpload(const ShadowPlan& o) const {
    if (!(*this == o)) return false;
    for (size_t i = 0; i < lights.size(); ++i)
        if (lights[i].firstFace != o.lights[i].firstFace) return false;
    return faces.empty() ||
           std::memcmp(faces.data(), o.faces.data(), faces.size() * sizeof(gpu::ShadowFace)) == 0;
}

} // namespace tp
