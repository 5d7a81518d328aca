# Per-test link needs beyond an area's default (included by tests/CMakeLists.txt).
# hfxc's --annotations / --reflect output is read back with cJSON, as the hfxc program writes it.
if(TARGET tools_test_hfxc AND TARGET hfx_cjson)
  target_link_libraries(tools_test_hfxc PRIVATE hfx_cjson)
  target_compile_definitions(tools_test_hfxc PRIVATE HFX_HAVE_CJSON=1)
endif()
if(TARGET tools_test_hfxc AND TARGET hfxc)
  add_dependencies(tools_test_hfxc hfxc) # the test runs the built program
endif()

# runtime_only: a program linked with hfx_runtime alone (no compiler) loads the .hfxo files hfxc
# writes and renders the pixels hfx renders from the .fx. hfxo_reference (linked with hfx) draws
# the same scenes from the .fx first (a fixture) and leaves raw RGBA pictures for the comparison.
set(HFX_RTONLY_DIR ${CMAKE_CURRENT_SOURCE_DIR}/runtime_only)
set(HFX_RTONLY_REFS ${CMAKE_CURRENT_BINARY_DIR}/runtime_only/references)
file(MAKE_DIRECTORY ${HFX_RTONLY_REFS})
set(HFX_RTONLY_SCENES ${HFX_RTONLY_DIR}/support/rto_scenes.c ${CMAKE_CURRENT_SOURCE_DIR}/seeds/support/seedmath.c)
set(HFX_RTONLY_INCLUDES ${HFX_RTONLY_DIR}/support ${CMAKE_CURRENT_SOURCE_DIR}/seeds/support)

add_executable(runtime_only_hfxo_reference ${HFX_RTONLY_DIR}/hfxo_reference.c ${HFX_RTONLY_SCENES})
target_include_directories(runtime_only_hfxo_reference PRIVATE ${HFX_RTONLY_INCLUDES})
target_link_libraries(runtime_only_hfxo_reference PRIVATE hfx hfx_test_harness m)
add_test(NAME runtime_only/hfxo_reference COMMAND runtime_only_hfxo_reference ${HFX_RTONLY_REFS}
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(runtime_only/hfxo_reference PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600 LABELS runtime_only
  ENVIRONMENT "HFX_BUILD_DIR=${CMAKE_BINARY_DIR}" FIXTURES_SETUP hfx_rtonly_references)

add_executable(runtime_only_test_hfxo_runtime ${HFX_RTONLY_DIR}/test_hfxo_runtime.c ${HFX_RTONLY_SCENES})
target_include_directories(runtime_only_test_hfxo_runtime PRIVATE ${HFX_RTONLY_INCLUDES})
target_link_libraries(runtime_only_test_hfxo_runtime PRIVATE hfx_runtime hfx_test_harness m)
if(TARGET hfxc)
  add_dependencies(runtime_only_test_hfxo_runtime hfxc) # the test runs the built program
endif()
add_test(NAME runtime_only/test_hfxo_runtime COMMAND runtime_only_test_hfxo_runtime ${HFX_RTONLY_REFS}
  WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(runtime_only/test_hfxo_runtime PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 600 LABELS runtime_only
  ENVIRONMENT "HFX_BUILD_DIR=${CMAKE_BINARY_DIR}" FIXTURES_REQUIRED hfx_rtonly_references)

# The compiler must not reach that program, directly or through a library it links.
function(hfx_rtonly_assert_no_compiler target)
  set(seen "")
  set(todo ${target})
  while(todo)
    list(POP_FRONT todo t)
    if(t IN_LIST seen OR NOT TARGET ${t})
      continue()
    endif()
    list(APPEND seen ${t})
    if(t STREQUAL "hfx_compiler" OR t STREQUAL "hfx")
      message(FATAL_ERROR "${target} links ${t}: runtime_only tests must link hfx_runtime alone")
    endif()
    get_target_property(libs ${t} LINK_LIBRARIES)
    get_target_property(ilibs ${t} INTERFACE_LINK_LIBRARIES)
    foreach(l IN LISTS libs ilibs)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" l "${l}") # static libraries' private deps
      if(l AND NOT l MATCHES "NOTFOUND$")
        list(APPEND todo ${l})
      endif()
    endforeach()
  endwhile()
endfunction()
hfx_rtonly_assert_no_compiler(runtime_only_test_hfxo_runtime)

# And the linked executable holds no compiler code: nm finds none of libhfx_compiler.a's global
# symbols defined in it, while it does in hfxo_reference (linked with hfx): the check can see them.
if(CMAKE_NM)
  add_test(NAME runtime_only/no_compiler_symbols
    COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} -DRUNTIME_ONLY=$<TARGET_FILE:runtime_only_test_hfxo_runtime>
            -DWITH_COMPILER=$<TARGET_FILE:runtime_only_hfxo_reference> -DCOMPILER_LIB=$<TARGET_FILE:hfx_compiler>
            -P ${HFX_RTONLY_DIR}/no_compiler_symbols.cmake)
  set_tests_properties(runtime_only/no_compiler_symbols PROPERTIES LABELS runtime_only)
endif()

# tests/runtime/test_targets.c draws the same scenes with the GLSL 110 and ES 300 targets.
if(TARGET runtime_test_targets)
  target_sources(runtime_test_targets PRIVATE ${HFX_RTONLY_SCENES})
  target_include_directories(runtime_test_targets PRIVATE ${HFX_RTONLY_INCLUDES})
endif()

# hfx_add_effects in an outside project: it includes cmake/hfxEffects.cmake and runs the built hfxc.
if(TARGET tools_test_hfx_add_effects)
  target_compile_definitions(tools_test_hfx_add_effects PRIVATE HFX_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  if(TARGET hfxc)
    add_dependencies(tools_test_hfx_add_effects hfxc)
  endif()
endif()

# Allocation failure (tests/alloc): the program wraps the allocator at link time, so the
# libraries carry no hook; allocation N fails for every N in turn.
add_executable(alloc_test_alloc_failure ${CMAKE_CURRENT_SOURCE_DIR}/alloc/test_alloc_failure.c)
target_include_directories(alloc_test_alloc_failure PRIVATE ${PROJECT_SOURCE_DIR}/common)
target_link_libraries(alloc_test_alloc_failure PRIVATE hfx hfx_test_harness m)
target_link_options(alloc_test_alloc_failure PRIVATE -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=strdup)
add_test(NAME alloc/test_alloc_failure COMMAND alloc_test_alloc_failure WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties(alloc/test_alloc_failure PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 900 LABELS alloc)
