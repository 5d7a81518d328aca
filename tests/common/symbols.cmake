# The names hfx's libraries give the programs that link them (docs/conventions.md, "Names"):
#  1. every global symbol the static libraries define starts with the project's prefix, hfx_
#     (hfxc_ for the compiler's public API), so a program's own sb_put or ir_lower never clashes;
#  2. the shared libhfx.so exports exactly the functions include/hfx/*.h declare with HFX_API:
#     none missing (a declaration without a definition, or one left hidden), none extra.
#   cmake -DNM=nm -DSOURCE_DIR=<hfx> -DSHARED=<libhfx.so> -DARCHIVES="a;b" -DVULKAN=ON|OFF -P symbols.cmake
cmake_minimum_required(VERSION 3.20)

include(${CMAKE_CURRENT_LIST_DIR}/nm_names.cmake)

# 1. The static libraries.
set(bad)
set(total 0)
foreach(a ${ARCHIVES})
  nm_names(names A-Za-z -g --defined-only ${a}) # the global symbols it defines (T, D, B, R, V, W, ...)
  list(LENGTH names n)
  math(EXPR total "${total} + ${n}")
  foreach(s ${names})
    if(NOT s MATCHES "^hfxc?_" AND NOT s MATCHES "^__") # __: the toolchain's (ASan's __odr_asan.*)
      get_filename_component(lib ${a} NAME)
      list(APPEND bad "${lib}: ${s}")
    endif()
  endforeach()
endforeach()
if(total LESS 300)
  message(FATAL_ERROR "symbols: only ${total} global symbols in ${ARCHIVES}: wrong files?")
endif()
list(LENGTH bad nbad)
if(nbad GREATER 0)
  list(JOIN bad "\n  " text)
  message(FATAL_ERROR "symbols: ${nbad} global names without the hfx_ prefix:\n  ${text}")
endif()
message(STATUS "symbols: ${total} global names in the static libraries, all prefixed")

# 2. The shared library against the public headers.
set(headers hfx.h hfxc.h)
if(VULKAN)
  list(APPEND headers hfx_vulkan.h)
endif()
set(declared)
foreach(h ${headers})
  file(READ ${SOURCE_DIR}/include/hfx/${h} text)
  string(REGEX MATCHALL "\nHFX_API [^(;]*[ *](hfxc?_[a-z0-9_]+)\\(" decls "${text}")
  foreach(d ${decls})
    string(REGEX REPLACE ".*[ *](hfxc?_[a-z0-9_]+)\\($" "\\1" name "${d}")
    list(APPEND declared ${name})
  endforeach()
endforeach()
list(LENGTH declared ndeclared)
if(ndeclared LESS 80)
  message(FATAL_ERROR "symbols: only ${ndeclared} HFX_API declarations read from ${headers}")
endif()
nm_names(exported A-Za-z -D --defined-only ${SHARED})
set(missing ${declared})
list(REMOVE_ITEM missing ${exported})
set(extra ${exported})
list(REMOVE_ITEM extra ${declared})
if(missing OR extra)
  list(JOIN missing " " m)
  list(JOIN extra " " e)
  message(FATAL_ERROR "symbols: libhfx.so exports differ from the HFX_API declarations\n"
    "  declared, not exported: ${m}\n  exported, not declared: ${e}")
endif()
message(STATUS "symbols: libhfx.so exports the ${ndeclared} HFX_API functions and nothing else")
