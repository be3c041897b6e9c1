#version 460
#extension GL_GOOGLE_include_directive : require
// Renders the scene into one shadow-map face (core/passes/shadow_maps.cpp): DrawPush.pad0 is
// the face. Light-relative, as the sampling computes it (include/shadow_sample.glsl): the
// camera-relative vertex (scene.vert's subtraction) minus the camera-relative light.
// TP_SHADOW_MASK: with scene.vert's whole interface, for prepass_mask.frag's alpha test.
#include "include/shared.h"
#include "include/shadows.h"
#include "include/scene_bindings.glsl"

#include "include/shadow_faces.glsl"

#ifdef TP_SHADOW_MASK
layout(location = 0) out vec3 outPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
layout(location = 3) out vec4 outTangent;
layout(location = 4) out vec4 outColor;
layout(location = 5) out float outOne;
#endif

void main() {
    Vertex v = vertices[gl_VertexIndex];
    ShadowFace f = shadowFaces[draw.pad0];
    precise vec3 relative = v.positionU.xyz - frame.eyeWorld.xyz;
    precise vec3 fromLight = relative - lights[f.atlas.w].position;
#ifdef TP_SHADOW_MASK
    outPosition = relative;
    outNormal = v.normalV.xyz;
    outUv = vec2(v.positionU.w, v.normalV.w);
    outTangent = v.tangent;
    outColor = v.color;
    outOne = 1.0;
#endif
    gl_Position = f.lightProj * vec4(fromLight, 1.0);
}
