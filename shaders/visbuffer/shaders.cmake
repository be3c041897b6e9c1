# Visibility buffer shaders (names are what visbuffer/*.cpp and core/passes ask for).
# The visibility pass: opaque (no material) and alpha-masked (the alpha test per sample).
triptych_add_shader(SPVS ${SHADER_DIR}/visibility.frag vis_visibility_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/visibility.frag vis_visibility_masked_frag DEFINES TP_VIS_MASKED=1)
# Both drawing culled meshlets (--cull-geometry frustum): the ids mapped back to the draw's triangles.
triptych_add_shader(SPVS ${SHADER_DIR}/visibility.frag vis_visibility_meshlet_frag DEFINES TP_VIS_MESHLETS=1)
triptych_add_shader(SPVS ${SHADER_DIR}/visibility.frag vis_visibility_masked_meshlet_frag
  DEFINES TP_VIS_MASKED=1 TP_VIS_MESHLETS=1)
# --vis-blended compute: the blended fragment lists.
triptych_add_shader(SPVS ${SHADER_DIR}/blended_ids.frag vis_blended_ids_frag)
# The same, recording the blended depth bounds too (passes/blended_bounds.frag's two rates).
triptych_add_shader(SPVS ${SHADER_DIR}/blended_ids.frag vis_blended_ids_bounds_frag
  DEFINES TP_VIS_BLEND_BOUNDS=1)
triptych_add_shader(SPVS ${SHADER_DIR}/blended_ids.frag vis_blended_ids_bounds_pixel_frag
  DEFINES TP_VIS_BLEND_BOUNDS=1 TP_INPUTS_AT_PIXEL=1)

# The resolve: the library's tiled lighting with the visibility buffer's surface reader and
# pixel (vis_resolve.comp), the variant key of passes/tiled_lighting.h: m 0/1/2 (single-sample
# ids, per-sample ids, and per-sample hdr for the forward blended pass under MSAA), t, d,
# _h16, each with its _shadow twin. e stays 0: emission comes from the material.
triptych_tiled_lighting_variants(vis_tiled ${SHADER_DIR}/vis_resolve.comp MS 0 1 2 ES 0 TS 0 1)
# --vis-blended compute: the composite in the resolve (never per-sample hdr, always the
# transparent lists the blended fragments are lit from).
triptych_tiled_lighting_variants(vis_tiled_blend ${SHADER_DIR}/vis_resolve.comp MS 0 1 ES 0 TS 1
  DEFINES TP_VIS_BLEND=1)
# --vis-raster compute|hybrid: the compute rasterizer (vis_raster.glsl), its large triangles
# (compute mode), the samples into the visibility targets (the seed at 1x, the merge under
# MSAA) and (hybrid) the hardware's triangles.
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster.comp vis_raster_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster.comp vis_raster_meshlet_comp DEFINES TP_VR_MESHLETS=1)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster_big.comp vis_raster_big_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster_order.comp vis_raster_order_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster_seed.comp vis_raster_seed_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster_merge.vert vis_raster_merge_vert)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster_merge.frag vis_raster_merge_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster_hw.vert vis_raster_hw_vert)
triptych_add_shader(SPVS ${SHADER_DIR}/vis_raster_hw.frag vis_raster_hw_frag)
