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
# The blended forward pass: per sample (1x, --msaa-shading sample) or, under MSAA at
# --msaa-shading pixel, once per pixel at its centre (as Forward+'s and multipass's blended draws).
# Each with its _shadow twin (--shadows: the blended surfaces sample the atlas too).
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/transparent.frag deferred_transparent_frag)
triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/transparent.frag deferred_transparent_pixel_frag DEFINES TP_INPUTS_AT_PIXEL=1)
# Tiled lighting variants where the set-1 resources differ: m = 0 single-sample G-buffer,
# 1 per-sample G-buffer, 2 per-sample G-buffer and per-sample hdr (blended under MSAA);
# e = emissive target; t = transparent light lists; d = debug outputs; each also with the
# suffix _h16 for an RGBA16F hdr (--hdr fp16: a storage image's format is in the shader).
# Each with its _shadow twin (--shadows: the lights' visibility in the shadow atlas, set 2),
# 96 in all (docs/deferred.md, "Shadows": what they add to the build).
foreach(m 0 1 2)
  foreach(e 0 1)
    foreach(t 0 1)
      foreach(d 0 1)
        set(defs TP_EMISSIVE=${e})
        if(m GREATER 0)
          list(APPEND defs TP_MSAA=1)
        endif()
        if(m EQUAL 2)
          list(APPEND defs TP_HDR_MSAA=1)
        endif()
        if(t)
          list(APPEND defs TP_TRANSPARENT=1)
        endif()
        if(d)
          list(APPEND defs TP_DEBUG=1)
        endif()
        triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/tiled_lighting.comp
          deferred_tiled_m${m}_e${e}_t${t}_d${d}_comp DEFINES ${defs})
        triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/tiled_lighting.comp
          deferred_tiled_m${m}_e${e}_t${t}_d${d}_h16_comp DEFINES ${defs} TP_HDR16=1)
      endforeach()
    endforeach()
  endforeach()
endforeach()
# Transparent light lists alone (volumes lighting of a blended scene): m = 0 / 1 as above.
triptych_add_shader(SPVS ${SHADER_DIR}/tiled_lighting.comp deferred_tiled_lists_m0_comp
  DEFINES TP_EMISSIVE=0 TP_TRANSPARENT=1 TP_LISTS_ONLY=1)
triptych_add_shader(SPVS ${SHADER_DIR}/tiled_lighting.comp deferred_tiled_lists_m1_comp
  DEFINES TP_EMISSIVE=0 TP_TRANSPARENT=1 TP_LISTS_ONLY=1 TP_MSAA=1)
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
