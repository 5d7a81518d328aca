# hfxEffects.cmake: hfx_add_effects, effects compiled to .hfxo at build time.
#
#   hfx_add_effects(<target> [SOURCES] a.fx b.fx ...
#                   [OUTPUT_DIR dir]            # default: ${CMAKE_CURRENT_BINARY_DIR}/effects
#                   [DEFINES NAME NAME=VALUE ...]
#                   [INCLUDE_DIRS dir ...]
#                   [TARGETS glsl330 glsles300 glsl110 spirv]
#                   [OPTIONS --werror ...])      # anything else hfxc takes
#
# makes a custom target <target> (built by `all`) whose outputs are <OUTPUT_DIR>/<name>.hfxo, and
# sets <target>_OUTPUTS to their paths. hfxc writes a depfile per effect (-MD), which CMake hands
# to the generator (Ninja, or Makefiles with CMake >= 3.20), so touching an included .fxh
# recompiles exactly the effects that include it. hfxc is HFX_HFXC_EXECUTABLE: find_package(hfx)
# sets it to the installed one; inside hfx's own build it is the hfxc target. DEPFILE with the
# Makefile generators needs CMake 3.20.
if(CMAKE_VERSION VERSION_LESS 3.20)
  message(WARNING "hfx_add_effects needs CMake 3.20 for depfiles: changed includes will not rebuild effects")
endif()

function(_hfx_effect_command out src)
  cmake_parse_arguments(PARSE_ARGV 2 E "" "" "DEFINES;INCLUDE_DIRS;TARGETS;OPTIONS")
  set(args -q -o ${out} -MD -MF ${out}.d)
  foreach(d IN LISTS E_DEFINES)
    list(APPEND args -D ${d})
  endforeach()
  foreach(i IN LISTS E_INCLUDE_DIRS)
    get_filename_component(i "${i}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    list(APPEND args -I ${i})
  endforeach()
  if(E_TARGETS)
    string(REPLACE ";" "," targets "${E_TARGETS}")
    list(APPEND args --target ${targets})
  endif()
  get_filename_component(name ${src} NAME)
  add_custom_command(OUTPUT ${out}
    COMMAND ${HFX_HFXC_EXECUTABLE} ${args} ${E_OPTIONS} ${src}
    DEPENDS ${src} ${HFX_HFXC_EXECUTABLE}
    DEPFILE ${out}.d
    COMMENT "hfxc ${name}"
    VERBATIM)
endfunction()

function(hfx_add_effects target)
  cmake_parse_arguments(PARSE_ARGV 1 HFX "" "OUTPUT_DIR" "SOURCES;DEFINES;INCLUDE_DIRS;TARGETS;OPTIONS")
  if(NOT HFX_HFXC_EXECUTABLE)
    message(FATAL_ERROR "hfx_add_effects: HFX_HFXC_EXECUTABLE is not set (find_package(hfx) sets it)")
  endif()
  if(NOT HFX_OUTPUT_DIR)
    set(HFX_OUTPUT_DIR ${CMAKE_CURRENT_BINARY_DIR}/effects)
  endif()
  get_filename_component(dir "${HFX_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  file(MAKE_DIRECTORY ${dir})
  set(outputs)
  foreach(src IN LISTS HFX_SOURCES HFX_UNPARSED_ARGUMENTS)
    get_filename_component(src "${src}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(stem ${src} NAME_WE)
    set(out ${dir}/${stem}.hfxo)
    _hfx_effect_command(${out} ${src} DEFINES ${HFX_DEFINES} INCLUDE_DIRS ${HFX_INCLUDE_DIRS}
      TARGETS ${HFX_TARGETS} OPTIONS ${HFX_OPTIONS})
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${outputs})
  set(${target}_OUTPUTS ${outputs} PARENT_SCOPE)
endfunction()
