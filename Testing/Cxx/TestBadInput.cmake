# Each bad invocation of `vtkao render` must print one line on stderr, exit non-zero and
# leave no output file behind.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/malformed.vtp" "<VTKFile type=\"PolyData\"> this is not a mesh")
file(WRITE "${WORK}/points.vtk" "# vtk DataFile Version 3.0\npoints\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\n")
set(cases
  "missing file|${WORK}/missing.stl"
  "malformed file|${WORK}/malformed.vtp"
  "no polygons|${WORK}/points.vtk"
  "unknown option|--frobnicate"
  "unknown method|--method magic"
  "bad number|--rays many"
  "out of range|--rays 0"
  "bad size|--size 12by7"
  "unknown format|${WORK}/malformed.xyz"
  "aov: AO scale out of range|--method aov --ao-scale 9"
  "aov: negative radius|--method aov --radius -1"
  "aov: no polygons|--method aov --ao-only ${WORK}/points.vtk")
file(WRITE "${WORK}/malformed.xyz" "1 2 3\n")
set(failures 0)
foreach (case IN LISTS cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  separate_arguments(args UNIX_COMMAND "${args}")
  set(out "${WORK}/out.png")
  file(REMOVE "${out}")
  execute_process(COMMAND "${VTKAO}" render ${args} --output "${out}"
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  string(STRIP "${err}" err)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines lines)
  set(exists NO)
  if (EXISTS "${out}")
    set(exists YES)
  endif ()
  if (rc EQUAL 0 OR exists OR err STREQUAL "" OR lines GREATER 0)
    message(SEND_ERROR "${name}: rc=${rc}, output file left=${exists}, stderr='${err}'")
    math(EXPR failures "${failures} + 1")
  else ()
    message(STATUS "ok: ${name}: ${err}")
  endif ()
endforeach ()
# An output format the program cannot write.
execute_process(COMMAND "${VTKAO}" render --output "${WORK}/out.bmp"
  RESULT_VARIABLE rc ERROR_VARIABLE err)
string(STRIP "${err}" err)
if (rc EQUAL 0 OR EXISTS "${WORK}/out.bmp" OR err STREQUAL "" OR err MATCHES "\n")
  message(SEND_ERROR "bad output format: rc=${rc}, stderr='${err}'")
  math(EXPR failures "${failures} + 1")
else ()
  message(STATUS "ok: bad output format: ${err}")
endif ()
# An unwritable output directory: an error, nothing left behind.
execute_process(COMMAND "${VTKAO}" render --output "${WORK}/no/such/dir/out.png"
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if (rc EQUAL 0)
  message(SEND_ERROR "unwritable output: rc=0")
endif ()
if (failures)
  message(FATAL_ERROR "${failures} bad-input case(s) misbehaved")
endif ()
