# The viewer's composite on the GPU (viewer/gpu_composite.h, composite_shared.h).
triptych_add_shader(SPVS ${SHADER_DIR}/composite.comp viewer_composite_comp)
foreach(kind 0 1 2)
  triptych_add_shader(SPVS ${SHADER_DIR}/composite_stats.comp viewer_composite_stats_${kind}_comp
    DEFINES TP_VC_STATS=${kind})
endforeach()
