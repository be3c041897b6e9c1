# Visibility buffer shaders (names are what visbuffer/*.cpp and core/passes ask for).
# The visibility pass: opaque (no material) and alpha-masked (the alpha test per sample).
triptych_add_shader(SPVS ${SHADER_DIR}/visibility.frag vis_visibility_frag)
triptych_add_shader(SPVS ${SHADER_DIR}/visibility.frag vis_visibility_masked_frag DEFINES TP_VIS_MASKED=1)
# --vis-blended compute: the blended fragment lists.
triptych_add_shader(SPVS ${SHADER_DIR}/blended_ids.frag vis_blended_ids_frag)

# The resolve: the tiled lighting pass (shaders/deferred/tiled_lighting.comp) with the
# visibility buffer's surface reader (vis_read.glsl), in the variants the pass names
# (core/passes/tiled_lighting.cpp: shaderName): m = 0 single-sample ids, 1 per-sample ids,
# 2 per-sample ids and per-sample hdr (blended under MSAA, forward); t = transparent light
# lists; d = debug outputs; _h16 = RGBA16F hdr. e stays 0: emission comes from the material.
# Each with its _shadow twin (--shadows: the shadow atlas, set 2).
# Extra defines after the lists of m and t values.
function(vis_tiled_variants family ms ts)
  foreach(m ${ms})
    foreach(t ${ts})
      foreach(d 0 1)
        set(defs TP_VISBUFFER=1 TP_EMISSIVE=0 ${ARGN})
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
        set(name ${family}_m${m}_e0_t${t}_d${d})
        triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/../deferred/tiled_lighting.comp ${name}_comp DEFINES ${defs})
        triptych_add_shadowed_shader(SPVS ${SHADER_DIR}/../deferred/tiled_lighting.comp ${name}_h16_comp DEFINES ${defs} TP_HDR16=1)
      endforeach()
    endforeach()
  endforeach()
  set(SPVS ${SPVS} PARENT_SCOPE)
endfunction()
vis_tiled_variants(vis_tiled "0;1;2" "0;1")
# --vis-blended compute: the composite in the resolve (never per-sample hdr, always the
# transparent lists the blended fragments are lit from).
vis_tiled_variants(vis_tiled_blend "0;1" "1" TP_VIS_BLEND=1)
