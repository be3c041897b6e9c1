# G-buffer deferred shaders (names are what deferred/*.cpp asks core/gpu/pipelines for).
# G-buffer: once per pixel (TP_INPUTS_AT_PIXEL) or at every sample (--msaa-shading sample).
triptych_add_shader(SPVS ${SHADER_DIR}/gbuffer.frag deferred_gbuffer_frag DEFINES TP_INPUTS_AT_PIXEL=1)
triptych_add_shader(SPVS ${SHADER_DIR}/gbuffer.frag deferred_gbuffer_emissive_frag
  DEFINES TP_EMISSIVE=1 TP_INPUTS_AT_PIXEL=1)
# Masked draws under MSAA at pixel rate: the alpha test per sample, the coverage written.
triptych_add_shader(SPVS ${SHADER_DIR}/gbuffer.frag deferred_gbuffer_coverage_frag
  DEFINES TP_INPUTS_AT_PIXEL=1 TP_SAMPLE_COVERAGE=1)
triptych_add_shader(SPVS ${SHADER_DIR}/gbuffer.frag deferred_gbuffer_coverage_emissive_frag
  DEFINES TP_EMISSIVE=1 TP_INPUTS_AT_PIXEL=1 TP_SAMPLE_COVERAGE=1)
triptych_add_shader(SPVS ${SHADER_DIR}/gbuffer.frag deferred_gbuffer_sample_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/gbuffer.frag deferred_gbuffer_sample_emissive_frag DEFINES TP_EMISSIVE=1)
# Tiled lighting over the G-buffer (tiled_lighting.comp: the library's pass with
# gbuffer_read.glsl), the variant key of passes/tiled_lighting.h: m 0/1/2 (single-sample,
# per-sample G-buffer, and per-sample hdr for blended surfaces under MSAA), e 0/1 (emissive
# target), t, d, _h16, each with its _shadow twin: 96 in all (docs/deferred.md, "Shadows":
# what they add to the build).
triptych_tiled_lighting_variants(deferred_tiled ${SHADER_DIR}/tiled_lighting.comp
  MS 0 1 2 ES 0 1 TS 0 1)
# Transparent light lists alone (volumes lighting of a blended scene).
triptych_tiled_lighting_lists(deferred_tiled ${SHADER_DIR}/tiled_lighting.comp MS 0 1)
# Light volumes: m = per-sample G-buffer (edge pixels shaded per sample in the shader),
# e = emissive target (the base pass adds it once).
triptych_add_shader(SPVS ${SHADER_DIR}/fullscreen.vert deferred_fullscreen_vert)
triptych_add_shader(SPVS ${SHADER_DIR}/volume.vert deferred_volume_vert)
# m = 2: per-sample hdr (a blended scene under MSAA): the light pass runs per sample into
# hdr_msaa after volume_sample_base wrote each sample's ambient + emissive there.
# Each with its shadowed twin (_shadow_frag: --shadows, one light's map at a time).
foreach(m 0 1 2)
  set(msaa)
  if(m GREATER 0)
    set(msaa TP_MSAA=1)
  endif()
  if(m EQUAL 2)
    list(APPEND msaa TP_HDR_MSAA=1)
  endif()
  triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/volume_light.frag deferred_volume_light_m${m}_frag
    DEFINES TP_EMISSIVE=0 ${msaa})
endforeach()
foreach(e 0 1)
  foreach(m 0 1)
    set(msaa)
    if(m)
      set(msaa TP_MSAA=1)
    endif()
    triptych_add_shader(SPVS ${SHADER_DIR}/volume_base.frag deferred_volume_base_m${m}_e${e}_frag
      DEFINES TP_EMISSIVE=${e} ${msaa})
  endforeach()
  triptych_add_shader(SPVS ${SHADER_DIR}/volume_sample_base.frag deferred_volume_sample_base_e${e}_frag
    DEFINES TP_EMISSIVE=${e})
endforeach()
