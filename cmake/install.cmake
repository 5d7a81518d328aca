# install.cmake: `cmake --install BUILD [--prefix P]` puts in place
#   include/hfx/*.h, lib/libhfx{,_runtime,_compiler,_common}.a, bin/hfxc, bin/hfxview,
#   lib/pkgconfig/hfx.pc (and hfx-runtime.pc; `pkg-config --variable=hfxc hfx` is hfxc's path) and
#   lib/cmake/hfx/ (find_package(hfx): hfx::hfx, hfx::hfx_runtime, hfx::hfx_compiler, hfx::hfx_common,
#   HFX_HFXC_EXECUTABLE and hfx_add_effects from hfxEffects.cmake).
# The libraries are static; the compiler carries glslang (C++ inside), so programs linking
# hfx also link glslang's libraries, libstdc++, pthread and libm: both files list them.
include(CMakePackageConfigHelpers)

set(HFX_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/hfx)
set(HFX_INSTALL_PKGCONFIGDIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(TARGETS hfx hfx_runtime hfx_compiler hfx_common
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(tool hfxc hfxview)
  if(TARGET ${tool})
    install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/hfx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h")

# What the compiler needs at link time, as -l flags (pkg-config) and as paths (CMake).
set(HFX_PC_EXTRA_LIBS "")
set(HFX_CMAKE_EXTRA_LIBS "")
if(TARGET hfx_glslang)
  foreach(lib ${HFX_GLSLANG_LIBS})
    if(HFX_GLSLANG_${lib})
      string(APPEND HFX_PC_EXTRA_LIBS " -l${lib}")
      list(APPEND HFX_CMAKE_EXTRA_LIBS "${HFX_GLSLANG_${lib}}")
    endif()
  endforeach()
  string(APPEND HFX_PC_EXTRA_LIBS " -lstdc++ -lpthread")
  list(APPEND HFX_CMAKE_EXTRA_LIBS stdc++ pthread)
endif()
string(APPEND HFX_PC_EXTRA_LIBS " -lm")
list(APPEND HFX_CMAKE_EXTRA_LIBS m)

# pkg-config: the static libraries go in Libs, since there is no shared build to prefer. The
# prefix is found from the .pc file's own place, so `--prefix` at install time just works.
file(RELATIVE_PATH HFX_PC_TO_PREFIX /root/${HFX_INSTALL_PKGCONFIGDIR} /root)
string(REGEX REPLACE "/$" "" HFX_PC_TO_PREFIX "${HFX_PC_TO_PREFIX}")
set(HFX_PC_NAME hfx)
set(HFX_PC_DESCRIPTION "Direct3D 9 effects (.fx) compiled to GLSL and run on OpenGL, with an XNA-like API")
set(HFX_PC_LIBS "-lhfx -lhfx_compiler -lhfx_common -lz${HFX_PC_EXTRA_LIBS}")
configure_file(${CMAKE_CURRENT_LIST_DIR}/hfx.pc.in ${PROJECT_BINARY_DIR}/hfx.pc @ONLY)
set(HFX_PC_NAME hfx-runtime)
set(HFX_PC_DESCRIPTION "The hfx runtime alone: loads compiled effects (.hfxo), no compiler")
set(HFX_PC_LIBS "-lhfx_runtime -lhfx_common -lz -lm")
set(HFX_CMAKE_RUNTIME_LIBS hfx::hfx_common)
if(HFX_VULKAN) # the Vulkan back end validates SPIR-V with SPIRV-Tools (C++ inside)
  string(APPEND HFX_PC_LIBS " -lSPIRV-Tools -lstdc++ -lpthread")
  list(APPEND HFX_CMAKE_RUNTIME_LIBS "${SPIRV_TOOLS_LIBRARY}" stdc++ pthread m)
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/hfx.pc.in ${PROJECT_BINARY_DIR}/hfx-runtime.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/hfx.pc ${PROJECT_BINARY_DIR}/hfx-runtime.pc
  DESTINATION ${HFX_INSTALL_PKGCONFIGDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/hfxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/hfxConfig.cmake
  INSTALL_DESTINATION ${HFX_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_LIBDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/hfxConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/hfxConfig.cmake ${PROJECT_BINARY_DIR}/hfxConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/hfxEffects.cmake DESTINATION ${HFX_INSTALL_CMAKEDIR})
