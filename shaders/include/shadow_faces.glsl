// The shadow faces of set TP_SET_SHADOW (include/shadows.h), as the map's render
// (shadow/shadow.vert) and its sampling (include/shadow_sample.glsl) read them.
#ifndef TP_SHADOW_FACES_GLSL
#define TP_SHADOW_FACES_GLSL
#include "include/shadows.h"
layout(std430, set = TP_SET_SHADOW, binding = TP_BINDING_SHADOW_FACES) readonly buffer ShadowFaceBlock {
    ShadowFace shadowFaces[];
};
#endif
