# multipass forward: base pass, one-light pass (the masked prepass shader is shared).
triptych_add_shader(SPVS ${SHADER_DIR}/base.frag mp_base_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/light.frag mp_light_frag)
