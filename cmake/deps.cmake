# Third-party components, all from Debian packages (scripts/deps.sh installs them).
find_package(BISON 3.5 REQUIRED)
find_program(RE2C_EXECUTABLE re2c REQUIRED)
find_package(PkgConfig REQUIRED)
# zlib: the .hfxo checksum (CRC-32) in the common library.
if(NOT TARGET ZLIB::ZLIB) # the WebAssembly build brings its own crc32 (cmake/wasm.cmake)
  find_package(ZLIB REQUIRED)
endif()

# OSMesa: headless OpenGL for tests, hfxview and examples.
pkg_check_modules(OSMESA IMPORTED_TARGET osmesa)
find_package(PNG)
find_library(CJSON_LIBRARY cjson)
find_path(CJSON_INCLUDE_DIR cjson/cJSON.h)
if(CJSON_LIBRARY AND CJSON_INCLUDE_DIR)
  add_library(hfx_cjson INTERFACE)
  target_link_libraries(hfx_cjson INTERFACE ${CJSON_LIBRARY})
  target_include_directories(hfx_cjson INTERFACE ${CJSON_INCLUDE_DIR})
endif()
find_path(STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb)
find_library(STB_LIBRARY stb)
# DevIL reads DDS files (compressed, cube and volume) for hfxview; optional
find_path(IL_INCLUDE_DIR IL/il.h)
find_library(IL_LIBRARY IL)
pkg_check_modules(GLFW IMPORTED_TARGET glfw3)

# glslang's C interface (static libraries in Debian, C++ inside: link order matters).
set(HFX_GLSLANG_LIBS glslang MachineIndependent OSDependent GenericCodeGen OGLCompiler
    glslang-default-resource-limits SPIRV SPIRV-Tools-opt SPIRV-Tools)
set(HFX_GLSLANG_PATHS)
foreach(lib ${HFX_GLSLANG_LIBS})
  find_library(HFX_GLSLANG_${lib} NAMES ${lib})
  if(HFX_GLSLANG_${lib})
    list(APPEND HFX_GLSLANG_PATHS ${HFX_GLSLANG_${lib}})
  endif()
endforeach()
find_path(GLSLANG_INCLUDE_DIR glslang/Include/glslang_c_interface.h)
if(GLSLANG_INCLUDE_DIR AND HFX_GLSLANG_glslang)
  add_library(hfx_glslang INTERFACE)
  target_include_directories(hfx_glslang INTERFACE ${GLSLANG_INCLUDE_DIR})
  target_link_libraries(hfx_glslang INTERFACE ${HFX_GLSLANG_PATHS} stdc++ pthread m)
endif()
find_program(GLSLANG_VALIDATOR glslangValidator)
# SPIRV-Tools' validator (C interface, C++ inside): the Vulkan back end checks every module
# before vkCreateShaderModule, since a driver given invalid SPIR-V is undefined behaviour.
find_path(SPIRV_TOOLS_INCLUDE_DIR spirv-tools/libspirv.h)
find_library(SPIRV_TOOLS_LIBRARY NAMES SPIRV-Tools)
if(SPIRV_TOOLS_INCLUDE_DIR AND SPIRV_TOOLS_LIBRARY)
  add_library(hfx_spirv_tools INTERFACE)
  target_include_directories(hfx_spirv_tools INTERFACE ${SPIRV_TOOLS_INCLUDE_DIR})
  target_link_libraries(hfx_spirv_tools INTERFACE ${SPIRV_TOOLS_LIBRARY} stdc++ pthread m)
endif()
