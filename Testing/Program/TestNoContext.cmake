# With no way to make an OpenGL context (no X display; for VTK 9.4+ also no EGL vendor and an
# OSMesa that cannot make a context either) `vtkao render` prints one line saying what to
# install or set, exits non-zero, writes no output file, and does not crash or abort in VTK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(
  COMMAND "${CMAKE_COMMAND}" -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY
          --unset=VTK_DEFAULT_OPENGL_WINDOW
          __EGL_VENDOR_LIBRARY_FILENAMES=${WORK}/no-such-vendor.json
          __EGL_VENDOR_LIBRARY_DIRS=${WORK}
          GALLIUM_DRIVER=no-such-driver
          "${VTKAO}" render --size 64x36 --output "${WORK}/none.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "rc=${rc}\nstdout: ${out}\nstderr: ${err}")
if (rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "expected a non-zero exit status, got '${rc}'")
endif ()
if (rc GREATER 2)
  message(FATAL_ERROR "exit status ${rc}: not vtkao's own error exit (crash or abort?)")
endif ()
if (EXISTS "${WORK}/none.png")
  message(FATAL_ERROR "an output file was written")
endif ()
string(STRIP "${err}" err)
string(REGEX MATCHALL "\n" newlines "${err}")
list(LENGTH newlines extra_lines)
if (NOT extra_lines EQUAL 0 OR NOT err MATCHES "^vtkao: no OpenGL context could be made")
  message(FATAL_ERROR "expected one line 'vtkao: no OpenGL context could be made...', got: ${err}")
endif ()
