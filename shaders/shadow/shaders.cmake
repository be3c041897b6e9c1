# Shadow maps (core/passes/shadow_maps.cpp): depth only for opaque draws; masked draws keep
# scene.vert's interface for prepass_mask.frag's alpha test.
triptych_add_shader(SPVS ${SHADER_DIR}/shadow.vert shadow_vert)
triptych_add_shader(SPVS ${SHADER_DIR}/shadow.vert shadow_mask_vert DEFINES TP_SHADOW_MASK=1)
# The faces' meshlet cull (core/passes/shadow_cull.h, --cull-geometry frustum|full): each face's
# frustum and its light's range per meshlet, indirect draws of the rest.
triptych_add_shader(SPVS ${SHADER_DIR}/shadow_cull.comp shadow_cull_comp)
# --shadow-raster compute (core/passes/shadow_raster.h): the culled meshlets' triangles
# rasterized in compute (include/raster_triangle.glsl), the large ones a workgroup each.
triptych_add_shader(SPVS ${SHADER_DIR}/shadow_raster.comp shadow_raster_comp)
triptych_add_shader(SPVS ${SHADER_DIR}/shadow_raster_big.comp shadow_raster_big_comp)
