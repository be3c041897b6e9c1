#version 460
#extension GL_GOOGLE_include_directive : require
// Classic deferred lighting: the bounding volume of one light per draw (firstInstance =
// 2 * light index + 1 when the CPU chose the cone), drawn with front faces culled so that
// only back faces rasterize (see volume_light.frag and docs/deferred.md for why back faces
// handle a camera inside the volume).
//   point (and wide spots): a UV sphere circumscribing the light's range sphere;
//   spot with outer angle <= 60 degrees: a 16-sided cone circumscribing the outer cone;
//   directional: a triangle covering the viewport.
// Every volume is grown by one pixel's footprint (`margin`) so that a pixel whose centre
// misses the light's region, but one of whose MSAA samples meets it, still gets a fragment
// (the shader then shades that edge pixel per sample).
#include "include/shared.h"
#include "deferred/deferred_shared.h"
#include "include/scene_bindings.glsl"

layout(constant_id = TP_DEF_SPEC_SPHERE_SCALE) const float kSphereScale = 1.0;
layout(location = 0) flat out uint outLight;

// Positions are camera-relative (shared.h, FrameUniforms): the eye is at the origin, so
// length(light.position) is the light's distance from it.

// Growth that moves the projected silhouette out by >= 1 pixel everywhere: a
// ball of radius m at distance D subtends >= m / D radians, and a pixel subtends <= 1/f
// radians anywhere on screen (f = focal length in pixels; the projection only stretches
// off-axis), so m = D / f with D bounding the distance of every point of the region.
float pixelMargin(LightGpu light) {
    float fx = abs(frame.proj[0][0]) * float(frame.viewport.x);
    float fy = abs(frame.proj[1][1]) * float(frame.viewport.y);
    float focalPx = 0.5 * min(fx, fy);
    return (length(light.position) + light.range) / focalPx;
}

// The cone grown by `margin` in every direction: the same half-angle with its apex moved
// back by margin / sin(outer) (a parallel offset of the sides) and its cap pushed out by
// margin. Returns the (camera-relative) position of vertex k and the distance bound of the mesh.
vec3 coneVertex(LightGpu light, uint k, float margin, out float extent) {
    float cosOuter = -light.spotOffset / light.spotScale;
    float sinOuter = sqrt(max(1.0 - cosOuter * cosOuter, 1e-8));
    float back = margin / sinOuter;
    float h = light.range + back + margin;
    float radius = h * sinOuter / cosOuter;
    vec3 axis = light.direction;
    vec3 t = normalize(cross(axis, abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(axis, t); // (t, b, axis) right-handed: winding is kept
    vec3 local = volumeConeVertex(k);
    extent = back + sqrt(h * h + radius * radius / pow(cos(TP_PI_DEF / float(TP_DEF_CONE_SEGMENTS)), 2.0));
    return light.position - axis * back + (t * local.x + b * local.y) * radius + axis * (local.z * h);
}

void main() {
    uint index = uint(gl_InstanceIndex) >> 1;
    bool cone = (uint(gl_InstanceIndex) & 1u) != 0u;
    LightGpu light = lights[index];
    outLight = index;
    uint k = uint(gl_VertexIndex);
    if (light.type == TP_LIGHT_DIRECTIONAL) {
        // Clockwise in NDC with y up (the viewport flips y): a back face, kept by the culling.
        const vec2 c[3] = vec2[](vec2(-1.0, -1.0), vec2(-1.0, 3.0), vec2(3.0, -1.0));
        gl_Position = vec4(c[min(k, 2u)], 0.0, 1.0);
        return;
    }
    float margin = pixelMargin(light);
    float extent;
    vec3 position;
    if (cone) {
        position = coneVertex(light, k, margin, extent);
    } else {
        extent = (light.range + margin) * kSphereScale;
        position = light.position + volumeSphereVertex(k) * extent;
    }
    vec4 clip = frame.viewProj * vec4(position, 1.0);
    // A finite far plane would clip back faces beyond it: a volume that may reach past it
    // is flattened onto depth 0, which passes the depth test everywhere (conservative).
    float far = frame.projParams.y;
    if (far > 0.0 && length(light.position) + extent > 0.999 * far)
        clip.z = 0.0;
    gl_Position = clip;
}
