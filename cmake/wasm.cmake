# The WebAssembly build (emcmake cmake; scripts/web.sh): the same libraries as the native
# build, plus web/ (the page's glue). What emscripten's sysroot lacks comes from here:
#   - zlib: hfx takes only crc32() from it; web/wasm/zlib has that one function;
#   - GL/glcorearb.h: the runtime's GL table is declared with the core profile's types, which
#     WebGL 2 shares; the header comes from the host (Debian's libgl-dev) and only its types
#     and enums are used (the entry points come through the loader, web/wasm/webgl.c).
# glslang is not built for WebAssembly: the compiler's self-check of the GLSL it prints is off
# there (the browser's own GLSL ES compiler still checks every shader when it links).
add_library(hfx_web_zlib STATIC ${PROJECT_SOURCE_DIR}/web/wasm/zlib/crc32.c)
target_include_directories(hfx_web_zlib PUBLIC ${PROJECT_SOURCE_DIR}/web/wasm/zlib)
add_library(ZLIB::ZLIB ALIAS hfx_web_zlib)

find_file(HFX_HOST_GLCOREARB glcorearb.h PATHS /usr/include/GL NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH REQUIRED)
configure_file(${HFX_HOST_GLCOREARB} ${CMAKE_BINARY_DIR}/wasm-include/GL/glcorearb.h COPYONLY)
include_directories(SYSTEM ${CMAKE_BINARY_DIR}/wasm-include)
