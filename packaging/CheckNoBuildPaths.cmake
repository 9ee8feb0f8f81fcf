# Fails when the program holds a path of the build machine's source or build tree, which an installed
# copy could not rely on (issue #19: it finds its scenes beside itself). Reads the printable strings
# of the binary as `strings` does. Usage (ctest "no_build_paths"):
#   cmake -DBINARY=<radiant> -DCONTROL=<a binary that holds SOURCE_DIR> -DSOURCE_DIR=<tree>
#         -DBINARY_DIR=<build folder> -P CheckNoBuildPaths.cmake
foreach(variable BINARY CONTROL SOURCE_DIR BINARY_DIR)
  if(NOT ${variable})
    message(FATAL_ERROR "CheckNoBuildPaths.cmake: pass -D${variable}=...")
  endif()
endforeach()

# The printable strings of a binary that contain any of the paths.
function(strings_naming out_var binary)
  file(STRINGS "${binary}" strings REGEX "/")
  set(hits "")
  foreach(string IN LISTS strings)
    foreach(path IN LISTS ARGN)
      string(FIND "${string}" "${path}" at)
      if(NOT at EQUAL -1)
        list(APPEND hits "${string}")
        break()
      endif()
    endforeach()
  endforeach()
  set(${out_var} "${hits}" PARENT_SCOPE)
endfunction()

strings_naming(control_hits "${CONTROL}" "${SOURCE_DIR}")
if(NOT control_hits)
  message(FATAL_ERROR "no_build_paths: the scan found no '${SOURCE_DIR}' in ${CONTROL}, which holds it on purpose: "
                      "the scan reads nothing")
endif()

strings_naming(hits "${BINARY}" "${SOURCE_DIR}" "${BINARY_DIR}")
if(hits)
  list(JOIN hits "\n  " listing)
  message(FATAL_ERROR "no_build_paths: ${BINARY} holds paths of the build machine (an installed copy cannot rely "
                      "on them):\n  ${listing}")
endif()
message(STATUS "no_build_paths: no '${SOURCE_DIR}' or '${BINARY_DIR}' in ${BINARY}")
