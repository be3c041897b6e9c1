// The interpolants of scene.vert as a fragment stage receives them, and the material at this
// fragment. Include after scene_bindings.glsl and material.glsl.
layout(location = 0) in vec3 inPosition; // camera-relative: world minus the eye (scene.vert)
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;
layout(location = 4) in vec4 inColor;

MaterialSample evalFragmentMaterial() {
    return evalMaterial(materials[draw.materialIndex], inPosition, inNormal, inUv, inTangent,
                        inColor, gl_FrontFacing);
}
