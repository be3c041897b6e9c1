// multipass forward's blended-light-draws pass (multipass_forward/blended_light_draw_pass.h,
// blended_light_draws.comp) and the blended light draws that read its output (light.frag's
// TP_MP_BLENDED_GPU variant): bindings in set TP_SET_PASS, the per-view tables the CPU writes and
// the word each indirect draw carries in its firstInstance. docs/multipass_forward.md, "Light
// lists on the GPU". The light and draw rows are the light-draws pass's (light_draws.h).
#ifndef TP_MP_BLENDED_LIGHT_DRAWS_H
#define TP_MP_BLENDED_LIGHT_DRAWS_H
#include "multipass_forward/light_draws.h"

#define TP_MPBL_BINDING_PARAMS 0   // BlendedLightDrawParams (per view)
#define TP_MPBL_BINDING_LIGHTS 1   // LightDrawLight per local light, in light order (per view);
                                   // also the blended light draws' set (their light, scissor)
#define TP_MPBL_BINDING_DRAWS 2    // LightDrawDraw per blended draw on screen, back to front
#define TP_MPBL_BINDING_COMMANDS 3 // VkDrawIndexedIndirectCommand: per blended draw a region of
                                   // 2 x lights (a light draw and its reset, in light order)
#define TP_MPBL_BINDING_COUNTS 4   // uint per blended draw: its commands written
#define TP_MPBL_BINDING_MESHES 5   // uint per light: the blended draws it lights

#define TP_MPBL_GROUP 64 // invocations per workgroup
// A command's firstInstance (scene_material_vert passes it to the fragment shader, flat): the
// light's slot (its row) and whether this is the transmittance reset after the light's draw.
#define TP_MPBL_RESET 0x80000000u
#define TP_MPBL_SLOT_MASK 0x7fffffffu

#ifndef TP_GLSL
namespace tp::gpu {
#endif

TP_STRUCT(BlendedLightDrawParams) {
    uint lightCount;   // local lights (rows of LightDrawLight)
    uint blendedCount; // blended draws on screen this view (rows of LightDrawDraw)
    uint boxTest;      // 1: the sphere-box test too (1x); 0: screen rectangles only (MSAA)
    uint pad0;
};

#ifndef TP_GLSL
static_assert(sizeof(BlendedLightDrawParams) == 16);
} // namespace tp::gpu
#endif
#endif
