# Finds every conversion from a floating type to an integer type, cast or implicit, in the
# libraries (common/, compiler/, runtime/ and their headers) with clang-query on the build's
# compile_commands.json, and fails on any outside the allow-list: C leaves an out-of-range or
# NaN conversion undefined, and hfx converts by Direct3D's rule through hfx_ev_int / hfx_ev_uint
# (common/eval.h; docs/conventions.md, "Float to integer").
#   cmake -DCLANG_QUERY=clang-query -DSOURCE_DIR=<hfx> -DBUILD_DIR=<build> -P float_casts.cmake
#
# The allow-list: functions whose casts are the rule itself. Add one only with a reason here.
#   hfx_ev_int, hfx_ev_uint (common/eval.c): the one conversion; the value is already truncated
#                                            into the target's range, so the cast is defined.
cmake_minimum_required(VERSION 3.20)
set(allowed hfx_ev_int hfx_ev_uint)

file(READ ${BUILD_DIR}/compile_commands.json db)
string(JSON n LENGTH "${db}")
math(EXPR last "${n} - 1")
set(files)
foreach(i RANGE ${last})
  string(JSON f GET "${db}" ${i} file)
  if(f MATCHES "^${SOURCE_DIR}/(common|compiler|runtime)/.*\\.c$")
    list(APPEND files ${f})
  endif()
endforeach()
list(REMOVE_DUPLICATES files)
list(LENGTH files count)
if(count LESS 50)
  message(FATAL_ERROR "float_casts: only ${count} library sources in ${BUILD_DIR}/compile_commands.json")
endif()

list(TRANSFORM allowed PREPEND "\"")
list(TRANSFORM allowed APPEND "\"")
list(JOIN allowed ", " names)
set(matcher "castExpr(hasCastKind(\"CK_FloatingToIntegral\"), isExpansionInFileMatching(\"^${SOURCE_DIR}/(common|compiler|runtime)/\"), unless(hasAncestor(functionDecl(hasAnyName(${names})))))")
execute_process(COMMAND ${CLANG_QUERY} -p ${BUILD_DIR} -c "set output diag" -c "match ${matcher}" ${files}
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
# A file that does not parse would hide its conversions: any error fails the check.
if(NOT rc EQUAL 0 OR err MATCHES "error:" OR NOT out MATCHES "[0-9]+ match(es)?\\.")
  message(FATAL_ERROR "float_casts: clang-query failed (exit ${rc}):\n${err}")
endif()
string(REGEX MATCHALL "[^\n]*: note: \"root\" binds here" found "${out}")
list(REMOVE_DUPLICATES found) # a header's line is found from every file that includes it
if(found)
  list(LENGTH found k)
  list(TRANSFORM found REPLACE ": note: \"root\" binds here" ": a raw float-to-integer conversion")
  list(JOIN found "\n" msg)
  message(FATAL_ERROR "float_casts: ${k} conversion(s) not through hfx_ev_int / hfx_ev_uint (common/eval.h):\n${msg}")
endif()
message(STATUS "float_casts: ${count} files, no raw float-to-integer conversion")
