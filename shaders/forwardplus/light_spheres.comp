#version 460
#extension GL_GOOGLE_include_directive : require
// Forward+: every light's view-space bounding sphere (lightSphereView: centre, padded range),
// once per frame, before the culling. A light is a candidate of every tile its rectangle
// covers (about 150 tiles at 1,024 lights of the default radius at 1280x720); the culling then
// reads 16 bytes per candidate instead of the light and a transform into view space each
// time. The same function on the same inputs: the culling's tests see the same values.
// Indexed by light (directional lights get an unused entry).
#include "include/shared.h"
#include "forwardplus/forwardplus_shared.h"
#include "include/scene_bindings.glsl"
#include "include/tile_culling.glsl"

layout(local_size_x = 64) in;

layout(std430, set = TP_SET_PASS, binding = TP_FP_BINDING_SPHERES) writeonly buffer SphereBlock {
    vec4 spheres[];
};

void main() {
    // A 2D grid of groups (forwardplus/light_spheres.cpp): more lights than 65,535 x 64.
    const uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
    if (i >= draw.TP_FP_SPHERE_COUNT) return;
    spheres[i] = lightSphereView(lights[i], frame.view);
}
