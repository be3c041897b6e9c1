// Set 0 declarations (the shared scene); GLSL only. Include after shared.h.
#ifndef TP_SCENE_BINDINGS_GLSL
#define TP_SCENE_BINDINGS_GLSL
layout(constant_id = TP_SPEC_TEXTURE_COUNT) const int kTextureCount = 1;
layout(constant_id = TP_SPEC_HAS_SPOT) const bool kHasSpot = true;
layout(constant_id = TP_SPEC_ALPHA_MODE) const uint kAlphaMode = TP_ALPHA_OPAQUE;

layout(std140, set = TP_SET_SCENE, binding = TP_BINDING_FRAME) uniform FrameBlock {
    FrameUniforms frame;
};
layout(std430, set = TP_SET_SCENE, binding = TP_BINDING_VERTICES) readonly buffer VertexBlock {
    Vertex vertices[];
};
layout(std430, set = TP_SET_SCENE, binding = TP_BINDING_MATERIALS) readonly buffer MaterialBlock {
    MaterialGpu materials[];
};
layout(std430, set = TP_SET_SCENE, binding = TP_BINDING_LIGHTS) readonly buffer LightBlock {
    LightGpu lights[];
};
layout(set = TP_SET_SCENE, binding = TP_BINDING_TEXTURES) uniform sampler2D textures[kTextureCount];

layout(push_constant) uniform DrawBlock {
    DrawPush draw;
};

// scene.vert's flat material output (TP_VERT_MATERIAL_INSTANCE) and scene_inputs.glsl's input
// (TP_MATERIAL_FROM_INSTANCE); 6 is the meshlet triangle (include/meshlets.h).
#define TP_LOCATION_MATERIAL 7
#endif
