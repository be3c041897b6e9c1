// The lights' uniform-buffer copy (include/lights_ubo.h). The includer defines
// TP_LIGHTS_UBO_BINDING (the binding in its pass set) and TP_LIGHTS_UBO_SPEC (the constant
// that says whether the copy is read; the host binds a one-light stand-in otherwise), after
// include/scene_bindings.glsl.
#ifndef TP_LIGHTS_UBO_GLSL
#define TP_LIGHTS_UBO_GLSL
#include "include/lights_ubo.h"

layout(constant_id = TP_LIGHTS_UBO_SPEC) const bool kLightsUbo = false;
layout(std140, set = TP_SET_PASS, binding = TP_LIGHTS_UBO_BINDING) uniform LightUboBlock {
    LightGpu uboLights[TP_LIGHTS_UBO_CAPACITY];
};

// Slot `slot` of the copy (what it holds at each slot is the host's layout: LightsUbo).
// Member by member: the block's std140 struct is another SPIR-V type than LightGpu, and a
// whole-struct copy between the two is not valid SPIR-V 1.0.
LightGpu uboLight(uint slot) {
    LightGpu l;
    l.position = uboLights[slot].position;
    l.range = uboLights[slot].range;
    l.direction = uboLights[slot].direction;
    l.type = uboLights[slot].type;
    l.color = uboLights[slot].color;
    l.shadow = uboLights[slot].shadow;
    l.spotScale = uboLights[slot].spotScale;
    l.spotOffset = uboLights[slot].spotOffset;
    l.pad1 = 0.0;
    l.pad2 = 0.0;
    return l;
}

// The scene's light `index`, for a copy with no prefix (slot k holds light k): from the copy
// where it is read, else from the scene's storage buffer.
LightGpu sceneLight(uint index) {
    if (kLightsUbo) return uboLight(index);
    return lights[index];
}
#endif
