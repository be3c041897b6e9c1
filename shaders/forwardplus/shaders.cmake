# Forward+ shaders (included by shaders/CMakeLists.txt with SHADER_DIR set).
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/shading.frag fp_shading_frag)
# --msaa-shading pixel under MSAA: once per pixel, inputs at the pixel centre (scene_inputs.glsl).
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/shading.frag fp_shading_pixel_frag DEFINES TP_INPUTS_AT_PIXEL=1)
# Culling: one variant per list layout, single-sample and multisampled depth; clustered
# (--light-assign clustered, compact layout: a list per tile over its depth span and per-slice
# bitmasks over it; the mask buffer binding exists only in these variants). Each twice: one
# invocation per tile (light_culling.comp) and --cull-by subgroup (light_culling_subgroup.comp).
foreach(by "" _subgroup)
  set(cull ${SHADER_DIR}/light_culling${by}.comp)
  foreach(layout compact fixed linked)
    string(TOUPPER ${layout} LAYOUT_UPPER)
    triptych_add_shader(SPVS ${cull} fp_cull_${layout}${by}_comp DEFINES TP_FP_CULL_${LAYOUT_UPPER}=1)
    triptych_add_shader(SPVS ${cull} fp_cull_${layout}_ms${by}_comp
      DEFINES TP_FP_CULL_${LAYOUT_UPPER}=1 TP_FP_DEPTH_MS=1)
  endforeach()
  triptych_add_shader(SPVS ${cull} fp_cull_compact_clustered${by}_comp DEFINES TP_FP_CULL_COMPACT=1 TP_FP_CLUSTERED=1)
  triptych_add_shader(SPVS ${cull} fp_cull_compact_clustered_ms${by}_comp
    DEFINES TP_FP_CULL_COMPACT=1 TP_FP_CLUSTERED=1 TP_FP_DEPTH_MS=1)
endforeach()
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/shading.frag fp_shading_clustered_frag DEFINES TP_FP_CLUSTERED=1)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/shading.frag fp_shading_clustered_pixel_frag
  DEFINES TP_FP_CLUSTERED=1 TP_INPUTS_AT_PIXEL=1)
# --light-loop subgroup (clustered): the cluster loop scalarized over a subgroup that shades one
# tile; separate variants because they declare the subgroup capabilities.
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/shading.frag fp_shading_clustered_subgroup_frag
  DEFINES TP_FP_CLUSTERED=1 TP_FP_LIGHT_LOOP_SUBGROUP=1)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/shading.frag fp_shading_clustered_subgroup_pixel_frag
  DEFINES TP_FP_CLUSTERED=1 TP_FP_LIGHT_LOOP_SUBGROUP=1 TP_INPUTS_AT_PIXEL=1)
# Every light's view-space sphere, once per frame, for the culling.
triptych_add_shader(SPVS ${SHADER_DIR}/light_spheres.comp fp_light_spheres_comp)
