# The viewer's own dependencies: OpenGL, GLFW, Dear ImGui and the glad loader generator.
# Only the viewer's target (opal-view, defined next to where this is included) needs them,
# so they are looked for there and nowhere else: a headless build (a render node, CI)
# configures and builds without them. OPAL_BUILD_VIEWER decides:
#   AUTO (default)  build the viewer when all four are installed; otherwise say which
#                   Debian packages are missing and go on without it;
#   ON              require them: a missing one stops the configure step naming its package;
#   OFF             do not look for them at all.
# scripts/setup installs them all. Sets OPAL_WITH_VIEWER (TRUE or FALSE) for the caller.
set(OPAL_BUILD_VIEWER AUTO CACHE STRING "Build the viewer (needs OpenGL, GLFW, Dear ImGui, glad): AUTO, ON or OFF")
set_property(CACHE OPAL_BUILD_VIEWER PROPERTY STRINGS AUTO ON OFF)
set(OPAL_WITH_VIEWER FALSE)
if(NOT OPAL_BUILD_VIEWER MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "OPAL_BUILD_VIEWER is '${OPAL_BUILD_VIEWER}', expected AUTO, ON or OFF")
endif()

if(NOT OPAL_BUILD_VIEWER STREQUAL "OFF")
  set(OpenGL_GL_PREFERENCE GLVND)
  find_package(OpenGL QUIET)
  find_package(glfw3 CONFIG QUIET)
  pkg_check_modules(IMGUI QUIET IMPORTED_TARGET imgui)
  find_program(OPAL_GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH)

  set(opal_viewer_missing)
  foreach(dependency IN ITEMS "OpenGL_FOUND;OpenGL;libgl-dev" "glfw3_FOUND;GLFW;libglfw3-dev"
                              "IMGUI_FOUND;Dear ImGui;libimgui-dev"
                              "OPAL_GLAD_EXECUTABLE;glad (OpenGL loader generator);python3-glad")
    list(GET dependency 0 found)
    list(GET dependency 1 name)
    list(GET dependency 2 package)
    if(OPAL_BUILD_VIEWER STREQUAL "ON")
      opal_require(${found} "${name}" "${package}")
    elseif(NOT ${found})
      list(APPEND opal_viewer_missing ${package})
    endif()
  endforeach()

  if(opal_viewer_missing)
    list(JOIN opal_viewer_missing ", " missing)
    message(STATUS "Opal: the viewer is not built (missing Debian packages: ${missing}; scripts/setup installs them)")
  else()
    set(OPAL_WITH_VIEWER TRUE)
  endif()
endif()
