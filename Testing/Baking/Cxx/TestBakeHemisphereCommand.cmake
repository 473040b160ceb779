# `vtkao bake --method hemisphere` on a floor (y = 0, half-width 1) under a ceiling (y = 0.5,
# half-width 3), both in the input:
# - R = infinity: the floor corners see only the gaps beside the ceiling, A = 1 - F = 0.0317
#   (F: the point-to-rectangle form factors of the four ceiling parts); the ceiling is open, A = 1;
# - --radius 1: every floor point sees the ceiling within R only for cos(theta) >= h / R, so
#   A = (h / R)^2 = 0.25 everywhere on the floor;
# - a progress bar on stderr; the summary reports vertices/s;
# - --resolution out of range, or with another method, fails with one line and no file.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/mesh.vtk" "# vtk DataFile Version 3.0\nmesh\nASCII\nDATASET POLYDATA\n"
  "POINTS 8 float\n-1 0 -1  -1 0 1  1 0 1  1 0 -1  -3 0.5 -3  -3 0.5 3  3 0.5 3  3 0.5 -3\n"
  "POLYGONS 2 10\n4 0 1 2 3\n4 4 5 6 7\n")
set(failures 0)

# One line on stderr, a non-zero exit and no output file.
function(expect_usage_error name)
  execute_process(COMMAND "${VTKAO}" bake "${WORK}/mesh.vtk" ${ARGN}
    --output "${WORK}/${name}.vtp" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  string(STRIP "${err}" err)
  if (rc EQUAL 0 OR EXISTS "${WORK}/${name}.vtp" OR err STREQUAL "" OR err MATCHES "\n")
    message(SEND_ERROR "${name}: rc=${rc}, stderr='${err}'")
    math(EXPR failures "${failures} + 1")
    set(failures ${failures} PARENT_SCOPE)
  else ()
    message(STATUS "ok: ${name}: ${err}")
  endif ()
endfunction()
expect_usage_error(resolution-range --method hemisphere --resolution 4)
expect_usage_error(resolution-sattler --method sattler --resolution 32)

# Bake with @p args into @p name.vtp; sets lo and hi (the A range of the file) in the caller.
function(bake name)
  execute_process(COMMAND "${VTKAO}" bake "${WORK}/mesh.vtk" --method hemisphere ${ARGN}
    --output "${WORK}/${name}.vtp" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  file(GLOB partial "${WORK}/*.partial*")
  set(lo "" PARENT_SCOPE)
  set(hi "" PARENT_SCOPE)
  if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/${name}.vtp" OR partial)
    message(SEND_ERROR "${name}: hemisphere bake failed: rc=${rc}, partial='${partial}', stderr='${err}'")
    math(EXPR failures "${failures} + 1")
    set(failures ${failures} PARENT_SCOPE)
    return()
  endif ()
  # stderr is a pipe, not a terminal: start and end lines, no "\r" redraws (vtkaoProgram.h).
  string(ASCII 13 cr)
  string(FIND "${err}" "${cr}" cr_at)
  if (NOT err MATCHES "baking \\.\\.\\.\n" OR NOT err MATCHES "baking done \\(100%\\)" OR
      NOT cr_at EQUAL -1)
    message(SEND_ERROR "${name}: no start and end progress lines (or a terminal bar) on stderr: '${err}'")
    math(EXPR failures "${failures} + 1")
  endif ()
  if (NOT stdout MATCHES "hemisphere.*vertices/s")
    message(SEND_ERROR "${name}: no throughput in the summary: '${stdout}'")
    math(EXPR failures "${failures} + 1")
  endif ()
  set(failures ${failures} PARENT_SCOPE)
  message(STATUS "${name}: ${stdout}")
  file(READ "${WORK}/${name}.vtp" vtp)
  string(REGEX MATCH "Name=\"AmbientOcclusion\"[^>]*RangeMin=\"([0-9.e+-]+)\"[^>]*RangeMax=\"([0-9.e+-]+)\"" found "${vtp}")
  set(lo "${CMAKE_MATCH_1}" PARENT_SCOPE)
  set(hi "${CMAKE_MATCH_2}" PARENT_SCOPE)
endfunction()

bake(infinite --resolution 32 --bias 1e-4)
message(STATUS "R = infinity: A range ${lo} .. ${hi} (expected 0.0317 .. 1)")
if (lo STREQUAL "" OR lo LESS 0.0267 OR lo GREATER 0.0367 OR hi LESS 0.99)
  message(SEND_ERROR "R = infinity: A in [${lo}, ${hi}], expected [0.0317 +- 0.005, 1]")
  math(EXPR failures "${failures} + 1")
endif ()

bake(radius --resolution 32 --bias 1e-4 --radius 1)
message(STATUS "R = 1: A range ${lo} .. ${hi} (expected 0.25 .. 1)")
if (lo STREQUAL "" OR lo LESS 0.24 OR lo GREATER 0.26 OR hi LESS 0.99)
  message(SEND_ERROR "R = 1: A in [${lo}, ${hi}], expected [0.25 +- 0.01, 1]")
  math(EXPR failures "${failures} + 1")
endif ()

if (failures)
  message(FATAL_ERROR "${failures} hemisphere bake case(s) misbehaved")
endif ()
