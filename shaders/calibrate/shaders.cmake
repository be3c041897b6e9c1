# triptych calibrate: one variant per microbenchmark kind (calibrate_shared.h).
foreach(kind 0 1 2 3 4 5 6 8 9 10 15 16)
  triptych_add_shader(SPVS ${SHADER_DIR}/calibrate.comp calibrate_${kind}_comp DEFINES TP_CAL_KIND=${kind})
endforeach()
# The fragment-stage ceilings and the raster ones' constant colour.
foreach(kind 7 11 12 13 14 17)
  triptych_add_shader(SPVS ${SHADER_DIR}/calibrate.frag calibrate_${kind}_frag DEFINES TP_CAL_KIND=${kind})
endforeach()
foreach(vertex 0 1 2)
  triptych_add_shader(SPVS ${SHADER_DIR}/calibrate.vert calibrate_v${vertex}_vert DEFINES TP_CAL_VERTEX=${vertex})
endforeach()
