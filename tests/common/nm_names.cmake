# nm_names(<out> <letters> <nm arguments>...): the names `${NM} <nm arguments>` lists with a type
# letter matching the regex class <letters> ("A-Za-z": any; "TDBRtdbr": functions and data), the
# symbol version (@...) cut off, each name once. Shared by the -P scripts that read symbols
# (common/symbols.cmake, runtime_only/no_compiler_symbols.cmake).
function(nm_names out letters)
  execute_process(COMMAND ${NM} ${ARGN} OUTPUT_VARIABLE text ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} ${ARGN} failed (${rc}): ${err}")
  endif()
  string(REGEX MATCHALL "[0-9a-fA-F]+ [${letters}] [^\n]+" lines "${text}")
  set(names "")
  foreach(l IN LISTS lines)
    string(REGEX REPLACE "^[0-9a-fA-F]+ [${letters}] " "" name "${l}")
    string(REGEX REPLACE "@.*" "" name "${name}")
    list(APPEND names ${name})
  endforeach()
  list(REMOVE_DUPLICATES names)
  set(${out} ${names} PARENT_SCOPE)
endfunction()
