# multipass forward: base pass, one-light pass, blended transmittance reset, blended one-pass (the masked
# prepass shader is shared).
triptych_add_shader(SPVS ${SHADER_DIR}/base.frag mp_base_frag)
# Light passes: each also as its _shadow twin (--shadows: the light's own map, shadow_light.glsl).
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_frag)
# --msaa-shading pixel under MSAA: once per pixel, inputs at the pixel centre (scene_inputs.glsl).
triptych_add_shader(SPVS ${SHADER_DIR}/base.frag mp_base_pixel_frag DEFINES TP_INPUTS_AT_PIXEL=1)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_pixel_frag DEFINES TP_INPUTS_AT_PIXEL=1)
triptych_add_shader(SPVS ${SHADER_DIR}/alpha_reset.frag mp_alpha_reset_frag)
# --blended-lights one-pass: blended surfaces lit by every light in one pass.
triptych_add_shader(SPVS ${SHADER_DIR}/one_pass.frag mp_one_pass_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/one_pass.frag mp_one_pass_pixel_frag DEFINES TP_INPUTS_AT_PIXEL=1)
# --light-draws gpu: the light passes' draws are indirect (light_draws.comp writes them), each
# command's material in its firstInstance (scene_material_vert passes it on, flat).
triptych_add_shader(SPVS ${SHADER_DIR}/light_draws.comp mp_light_draws_comp)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_inst_frag
  DEFINES TP_MATERIAL_FROM_INSTANCE=1)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_inst_pixel_frag
  DEFINES TP_MATERIAL_FROM_INSTANCE=1 TP_INPUTS_AT_PIXEL=1)
# The light passes counting the fragments that evaluate their light (a GPU with pass statistics:
# TP_MP_LIGHT_PASS), with the CPU's lists and with the GPU's.
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_count_frag DEFINES TP_MP_LIGHT_PASS=1)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_count_pixel_frag
  DEFINES TP_INPUTS_AT_PIXEL=1 TP_MP_LIGHT_PASS=1)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_inst_count_frag
  DEFINES TP_MATERIAL_FROM_INSTANCE=1 TP_MP_LIGHT_PASS=1)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/light.frag mp_light_inst_count_pixel_frag
  DEFINES TP_MATERIAL_FROM_INSTANCE=1 TP_INPUTS_AT_PIXEL=1 TP_MP_LIGHT_PASS=1)
# Blended light draws and resets from the GPU's lists (blended_light_draws.comp writes them): one
# dual-source pipeline, the light's slot in each command's firstInstance.
triptych_add_shader(SPVS ${SHADER_DIR}/blended_light_draws.comp mp_blended_light_draws_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/light.frag mp_light_blend_frag DEFINES TP_MP_BLENDED_GPU=1)
triptych_add_shader(SPVS ${SHADER_DIR}/light.frag mp_light_blend_pixel_frag
  DEFINES TP_MP_BLENDED_GPU=1 TP_INPUTS_AT_PIXEL=1)
