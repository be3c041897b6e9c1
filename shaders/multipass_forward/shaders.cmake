# multipass forward: depth prepass (masked), base pass, one-light pass.
triptych_add_shader(SPVS ${SHADER_DIR}/prepass_mask.frag mp_prepass_mask_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/base.frag mp_base_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/light.frag mp_light_frag)
