#include "core/renderer/cull_geometry_knob.h"

namespace tp {

const ChoiceKnob<CullGeometry>& cullGeometryKnob() {
    static const ChoiceKnob<CullGeometry> k{
        "cull-geometry",
        {{CullGeometry::None, "none"},
         {CullGeometry::Frustum, "frustum"},
         {CullGeometry::Full, "full"}},
        "Meshlet culling on the GPU before the opaque and masked geometry passes: none (every "
        "mesh drawn whole), frustum (meshlets of at most 64 vertices and 124 triangles culled "
        "by bounding sphere against the view frustum and by normal cone when back-facing, the "
        "rest drawn with vkCmdDrawIndexedIndirectCount) or full (frustum and cone, then "
        "occlusion in two phases: the meshlets visible last frame are drawn, a depth pyramid is "
        "built from their depth, the rest are drawn where their bounding sphere is not wholly "
        "behind it; the first frame treats every meshlet as visible). Culled: Forward+'s depth "
        "prepass and opaque shading, deferred's G-buffer, the visibility buffer's visibility "
        "pass, multipass forward's depth prepass, base and light passes; with --shadows, frustum "
        "and full also cull every shadow face's meshlets by the face's frustum and the light's "
        "range (no occlusion, no cone: the maps see both sides), one compute dispatch per atlas "
        "render or per frame for the per-light maps; blended draws and the reference are drawn whole (docs/geometry.md, "
        "docs/shadows.md)"};
    return k;
}

} // namespace tp
