# multipass forward: base pass, one-light pass, blended transmittance reset (the masked
# prepass shader is shared).
triptych_add_shader(SPVS ${SHADER_DIR}/base.frag mp_base_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/light.frag mp_light_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/alpha_reset.frag mp_alpha_reset_frag)
