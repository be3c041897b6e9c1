# Light binning on the GPU (core/passes/light_binning.h): one shader per step of the
# light_binning pass, used by Forward+ and deferred (included by shaders/CMakeLists.txt).
foreach(step clear rects scan_rows scan_columns scan_words fill sort sort_step sort_local)
  triptych_add_shader(SPVS ${SHADER_DIR}/bin_${step}.comp la_bin_${step}_comp)
endforeach()
