# GLSL -> SPIR-V at build time with glslangValidator, then embedded in the binary as
# uint32 arrays so triptych runs from any directory.
#
# triptych_add_shader(<list-var> <source> <name> [DEFINES ...])
#   compiles <source> with -D<define> each into ${CMAKE_BINARY_DIR}/spv/<name>.spv and
#   appends the .spv path to <list-var>.
function(triptych_add_shader out_var source name)
  cmake_parse_arguments(ARG "" "" "DEFINES" ${ARGN})
  set(spv ${CMAKE_BINARY_DIR}/spv/${name}.spv)
  set(defs)
  foreach(d ${ARG_DEFINES})
    list(APPEND defs -D${d})
  endforeach()
  file(GLOB_RECURSE includes CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/shaders/*.h
    ${CMAKE_SOURCE_DIR}/shaders/*.glsl)
  add_custom_command(OUTPUT ${spv}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/spv
    COMMAND ${GLSLANG_VALIDATOR} --quiet -V --target-env vulkan1.3 -g0
      -I${CMAKE_SOURCE_DIR}/shaders -DTP_GLSL=1 ${defs} -o ${spv} ${source}
    DEPENDS ${source} ${includes}
    COMMENT "glslang ${name}"
    VERBATIM)
  set(${out_var} ${${out_var}} ${spv} PARENT_SCOPE)
endfunction()

# Writes one .cpp defining every shader as a named span, looked up by core/gpu/shaders: the
# bytes come in through the assembler's `.incbin` (embed_spv.cmake says why).
function(triptych_embed_shaders target)
  set(out ${CMAKE_BINARY_DIR}/embedded_shaders.cpp)
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} "-DSPVS=${ARGN}"
      -P ${CMAKE_SOURCE_DIR}/cmake/embed_spv.cmake
    DEPENDS ${ARGN} ${CMAKE_SOURCE_DIR}/cmake/embed_spv.cmake
    COMMENT "embedding SPIR-V"
    VERBATIM)
  # The file names the .spv files and `.incbin`s them (embed_spv.cmake): a recompiled shader
  # leaves it unchanged, so its object depends on the SPIR-V itself.
  set_source_files_properties(${out} PROPERTIES OBJECT_DEPENDS "${ARGN}")
  add_library(${target} STATIC ${out})
  # Compiled as itself, not through a unity file, so OBJECT_DEPENDS above is its object's.
  set_target_properties(${target} PROPERTIES UNITY_BUILD OFF)
  target_include_directories(${target} PUBLIC ${CMAKE_SOURCE_DIR})
endfunction()

# A shading shader and its shadowed twin: NAME, and NAME with "_shadow" before its stage suffix
# (fp_shading_frag -> fp_shading_shadow_frag) compiled with TP_SHADOW_MAPS (include/shadow_light.glsl).
# Without --shadows a pipeline uses NAME, the very SPIR-V it used before shadows existed.
function(triptych_add_shadowed_shader out_var source name)
  cmake_parse_arguments(ARG "" "" "DEFINES" ${ARGN})
  string(REGEX REPLACE "_([a-z]+)$" "_shadow_\\1" shadowed ${name})
  set(list ${${out_var}})
  triptych_add_shader(list ${source} ${name} DEFINES ${ARG_DEFINES})
  triptych_add_shader(list ${source} ${shadowed} DEFINES ${ARG_DEFINES} TP_SHADOW_MAPS=1)
  set(${out_var} ${list} PARENT_SCOPE)
endfunction()
