# The tiled lighting pass's variant matrix (core/passes/tiled_lighting.h), for every surface
# source: one function, the variant key read from passes/tiled_lighting.h (TP_TL_VARIANT_KEY,
# TP_TL_LISTS_KEY), where C++ reads it too.
file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/tiled_lighting.h TL_KEY_LINES
  REGEX "^#define TP_TL_(VARIANT|LISTS)_KEY ")
foreach(line ${TL_KEY_LINES})
  string(REGEX REPLACE "^#define TP_TL_([A-Z]+)_KEY \"([^\"]*)\".*" "\\1;\\2" kv "${line}")
  list(GET kv 0 which)
  list(GET kv 1 TL_${which}_KEY)
endforeach()
if(NOT TL_VARIANT_KEY OR NOT TL_LISTS_KEY)
  message(FATAL_ERROR "shaders/passes/tiled_lighting.h lacks TP_TL_VARIANT_KEY or TP_TL_LISTS_KEY")
endif()

# The defines of variant m (0 one sample, 1 per-sample surface, 2 per-sample surface and hdr).
function(tl_msaa_defines out m)
  set(defs)
  if(m GREATER 0)
    list(APPEND defs TP_MSAA=1)
  endif()
  if(m EQUAL 2)
    list(APPEND defs TP_HDR_MSAA=1)
  endif()
  set(${out} ${defs} PARENT_SCOPE)
endfunction()

# triptych_tiled_lighting_variants(<family> <entry shader> MS <m...> ES <e...> TS <t...>
#                                  [DEFINES <extra>...])
#   compiles <entry> (a surface source's entry shader: passes/tiled_lighting_inputs.glsl says
#   what it holds) as <family> + key + "_comp" and its _shadow twin, for every m, e and t given,
#   d (debug outputs) 0 and 1, and hdr RGBA32F and RGBA16F (_h16); appends them to SPVS.
function(triptych_tiled_lighting_variants family entry)
  cmake_parse_arguments(ARG "" "" "MS;ES;TS;DEFINES" ${ARGN})
  foreach(m ${ARG_MS})
    tl_msaa_defines(msaa ${m})
    foreach(e ${ARG_ES})
      foreach(t ${ARG_TS})
        foreach(d 0 1)
          set(defs TP_EMISSIVE=${e} ${ARG_DEFINES} ${msaa})
          if(t)
            list(APPEND defs TP_TRANSPARENT=1)
          endif()
          if(d)
            list(APPEND defs TP_DEBUG=1)
          endif()
          foreach(h "" "_h16")
            set(hdr)
            if(h)
              set(hdr TP_HDR16=1)
            endif()
            string(REPLACE "{m}" ${m} key "${TL_VARIANT_KEY}")
            string(REPLACE "{e}" ${e} key "${key}")
            string(REPLACE "{t}" ${t} key "${key}")
            string(REPLACE "{d}" ${d} key "${key}")
            string(REPLACE "{h}" "${h}" key "${key}")
            triptych_add_shadowed_shader(SPVS ${entry} ${family}${key}_comp DEFINES ${defs} ${hdr})
          endforeach()
        endforeach()
      endforeach()
    endforeach()
  endforeach()
  set(SPVS ${SPVS} PARENT_SCOPE)
endfunction()

# triptych_tiled_lighting_lists(<family> <entry shader> MS <m...>): the transparent light lists
# alone (TP_LISTS_ONLY: a surface source whose opaque surfaces another pass shades).
function(triptych_tiled_lighting_lists family entry)
  cmake_parse_arguments(ARG "" "" "MS" ${ARGN})
  foreach(m ${ARG_MS})
    tl_msaa_defines(msaa ${m})
    string(REPLACE "{m}" ${m} key "${TL_LISTS_KEY}")
    triptych_add_shader(SPVS ${entry} ${family}${key}_comp
      DEFINES TP_EMISSIVE=0 TP_TRANSPARENT=1 TP_LISTS_ONLY=1 ${msaa})
  endforeach()
  set(SPVS ${SPVS} PARENT_SCOPE)
endfunction()
