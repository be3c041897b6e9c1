# The pass library's own shaders (core/passes/; names are what its passes ask
# core/gpu/pipelines for). The tiled lighting pass is compiled per surface source, by the
# pipelines' lists (triptych_tiled_lighting_variants, passes/tiled_lighting.cmake).
# The masked depth prepass (and the shadow faces' alpha test).
triptych_add_shader(SPVS ${SHADER_DIR}/prepass_mask.frag prepass_mask_frag)
# Blended depth bounds (core/passes/blended_bounds.h): per-sample inputs / once per
# pixel (as the blended shading).
triptych_add_shader(SPVS ${SHADER_DIR}/blended_bounds.frag blended_bounds_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/blended_bounds.frag blended_bounds_pixel_frag
  DEFINES TP_INPUTS_AT_PIXEL=1)
# The same with scene.vert's whole interface (tests: BlendedBoundsConfig::fullInterface).
triptych_add_shader(SPVS ${SHADER_DIR}/blended_bounds.frag blended_bounds_full_frag
  DEFINES TP_LA_BLEND_FULL_INTERFACE=1)
triptych_add_shader(SPVS ${SHADER_DIR}/blended_bounds.frag blended_bounds_pixel_full_frag
  DEFINES TP_INPUTS_AT_PIXEL=1 TP_LA_BLEND_FULL_INTERFACE=1)
# The hybrid's blended forward pass (core/passes/blended_forward.h): per sample (1x,
# --msaa-shading sample) or, under MSAA at --msaa-shading pixel, once per pixel at its centre
# (as Forward+'s and multipass's blended draws). Each with its _shadow twin (--shadows: the
# blended surfaces sample the atlas too).
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/blended_forward.frag blended_forward_frag)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/blended_forward.frag blended_forward_pixel_frag
  DEFINES TP_INPUTS_AT_PIXEL=1)
# The compute clear of a colour image (core/passes/image_clear.h): per storage format,
# single-sample and multisampled.
foreach(f r32f rgba32f rgba16f)
  triptych_add_shader(SPVS ${SHADER_DIR}/image_clear.comp image_clear_${f}_comp DEFINES TP_IC_FORMAT=${f})
  triptych_add_shader(SPVS ${SHADER_DIR}/image_clear.comp image_clear_${f}_ms_comp
    DEFINES TP_IC_FORMAT=${f} TP_IC_MS=1)
endforeach()
# The meshlet cull pass (core/passes/meshlet_cull.h): frustum and normal cone per meshlet,
# indirect draws of the rest.
triptych_add_shader(SPVS ${SHADER_DIR}/meshlet_cull.comp meshlet_cull_comp)
# The tile depth bounds pass (core/passes/tile_depth_bounds.h), before the tiled lighting:
# single-sample and multisampled depth.
triptych_add_shader(SPVS ${SHADER_DIR}/tile_depth_bounds.comp tile_depth_bounds_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/tile_depth_bounds.comp tile_depth_bounds_ms_comp DEFINES TP_MSAA=1)
# --cull-geometry full: the early phase (last frame's visible meshlets) and the late one (the
# rest against the depth pyramid); each binds the visibility history, the late one the pyramid.
triptych_add_shader(SPVS ${SHADER_DIR}/meshlet_cull.comp meshlet_cull_early_comp
  DEFINES TP_MC_PHASE=1)
triptych_add_shader(SPVS ${SHADER_DIR}/meshlet_cull.comp meshlet_cull_late_comp
  DEFINES TP_MC_PHASE=2)
# The depth pyramid (core/passes/depth_pyramid.h) from a single-sample or an MSAA depth image.
triptych_add_shader(SPVS ${SHADER_DIR}/depth_pyramid.comp depth_pyramid_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/depth_pyramid.comp depth_pyramid_msaa_comp
  DEFINES TP_DP_MSAA=1)
