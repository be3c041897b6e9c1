# triptych calibrate: one variant per microbenchmark kind (calibrate_shared.h).
foreach(kind 0 1 2 3 4 5 6)
  triptych_add_shader(SPVS ${SHADER_DIR}/calibrate.comp calibrate_${kind}_comp DEFINES TP_CAL_KIND=${kind})
endforeach()
# The fragment-stage FMA ceiling, drawn with deferred's full-screen triangle.
triptych_add_shader(SPVS ${SHADER_DIR}/calibrate_fma.frag calibrate_fma_frag)
