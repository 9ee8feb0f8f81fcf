# The layers' include rule (docs/ARCHITECTURE.md): radiometry/, the solver library, runs without a
# display, so it includes no GL, GLFW, ImGui, render/ or app/; render/, the only GL code, includes no
# GLFW, ImGui or app/, so it draws for the lab, the tests and the command line alike. Fails naming each
# file and include that breaks the rule. Registered with ctest as "layering":
#   cmake -DRADIANT_SOURCE_DIR=<source tree> -P cmake/CheckLayering.cmake
if(NOT RADIANT_SOURCE_DIR)
  message(FATAL_ERROR "CheckLayering.cmake: pass -DRADIANT_SOURCE_DIR=<source tree>")
endif()

# Regular expressions on the included path (between <> or "").
set(gl_headers "^(GL|GLES[0-9]*|epoxy|glad|KHR)/")
set(glfw_headers "^(GLFW|glfw)/")
set(imgui_headers "(^|/)imgui")
set(forbidden_in_radiometry "${gl_headers}|${glfw_headers}|${imgui_headers}|^render/|^app/")
set(forbidden_in_render "${glfw_headers}|${imgui_headers}|^app/")

set(violations "")
foreach(layer radiometry render)
  if(NOT IS_DIRECTORY "${RADIANT_SOURCE_DIR}/${layer}")
    message(FATAL_ERROR "CheckLayering.cmake: no ${layer}/ in ${RADIANT_SOURCE_DIR}")
  endif()
  file(GLOB_RECURSE sources RELATIVE "${RADIANT_SOURCE_DIR}"
       "${RADIANT_SOURCE_DIR}/${layer}/*.h" "${RADIANT_SOURCE_DIR}/${layer}/*.hpp"
       "${RADIANT_SOURCE_DIR}/${layer}/*.cpp" "${RADIANT_SOURCE_DIR}/${layer}/*.inl")
  foreach(source IN LISTS sources)
    # Directives only: a comment that names a header is not an include.
    file(STRINGS "${RADIANT_SOURCE_DIR}/${source}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]*)[>\"].*$" "\\1" header "${line}")
      if(header MATCHES "${forbidden_in_${layer}}")
        list(APPEND violations "${source} includes ${header}")
      endif()
    endforeach()
  endforeach()
endforeach()

# render/display/, the display model, decides every colour without GL so tests/unit checks it with no
# context: no GL header, nothing of render/gl/.
file(GLOB_RECURSE display_sources RELATIVE "${RADIANT_SOURCE_DIR}" "${RADIANT_SOURCE_DIR}/render/display/*.h"
     "${RADIANT_SOURCE_DIR}/render/display/*.cpp")
foreach(source IN LISTS display_sources)
  file(STRINGS "${RADIANT_SOURCE_DIR}/${source}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]*)[>\"].*$" "\\1" header "${line}")
    if(header MATCHES "${gl_headers}|^render/gl/|^render/PatchRenderer")
      list(APPEND violations "${source} includes ${header} (render/display/ is GL-free)")
    endif()
  endforeach()
endforeach()

if(violations)
  list(JOIN violations "\n  " listing)
  message(FATAL_ERROR "layering: radiometry/ may not include GL, GLFW, ImGui, render/ or app/; render/ may "
                      "not include GLFW, ImGui or app/:\n  ${listing}")
endif()
message(STATUS "layering: radiometry/ and render/ include only what their layer allows")
