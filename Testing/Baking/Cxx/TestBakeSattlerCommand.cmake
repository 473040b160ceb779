# `vtkao bake --method sattler` and `vtkao render --method baked` on the baked file:
# - a floor (y = 0, half-width 1) under a ceiling (y = 0.5, half-width 3): with R = infinity the
#   floor corners see only the gaps beside the ceiling, A = 1 - F = 0.0317 (F: the point-to-
#   rectangle form factors of the four ceiling parts); the ceiling (normal +y) is open, A = 1;
# - a progress bar on stderr; the summary reports vertex-directions per second;
# - an unknown bake method fails with one line and no file;
# - `render baked.vtp --method baked --ao-only` uses the stored array (no re-bake).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/mesh.vtk" "# vtk DataFile Version 3.0\nmesh\nASCII\nDATASET POLYDATA\n"
  "POINTS 8 float\n-1 0 -1  -1 0 1  1 0 1  1 0 -1  -3 0.5 -3  -3 0.5 3  3 0.5 3  3 0.5 -3\n"
  "POLYGONS 2 10\n4 0 1 2 3\n4 4 5 6 7\n")
set(failures 0)

execute_process(COMMAND "${VTKAO}" bake "${WORK}/mesh.vtk" --method hemicube
  --output "${WORK}/bad.vtp" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
string(STRIP "${err}" err)
if (rc EQUAL 0 OR EXISTS "${WORK}/bad.vtp" OR err STREQUAL "" OR err MATCHES "\n")
  message(SEND_ERROR "unknown bake method: rc=${rc}, stderr='${err}'")
  math(EXPR failures "${failures} + 1")
endif ()

execute_process(COMMAND "${VTKAO}" bake "${WORK}/mesh.vtk" --method sattler --samples 1024
  --bias 1e-4 --output "${WORK}/baked.vtp"
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
file(GLOB partial "${WORK}/*.partial*")
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/baked.vtp" OR partial)
  message(SEND_ERROR "sattler bake failed: rc=${rc}, partial='${partial}', stderr='${err}'")
  math(EXPR failures "${failures} + 1")
else ()
  file(READ "${WORK}/baked.vtp" vtp)
  string(REGEX MATCH "Name=\"AmbientOcclusion\"[^>]*RangeMin=\"([0-9.e+-]+)\"[^>]*RangeMax=\"([0-9.e+-]+)\"" found "${vtp}")
  set(lo "${CMAKE_MATCH_1}")
  set(hi "${CMAKE_MATCH_2}")
  message(STATUS "A range: ${lo} .. ${hi} (expected 0.0317 .. 1)")
  if (NOT found OR lo LESS 0.0217 OR lo GREATER 0.0417 OR hi LESS 0.99)
    message(SEND_ERROR "baked.vtp: A in [${lo}, ${hi}], expected [0.0317 +- 0.01, 1]")
    math(EXPR failures "${failures} + 1")
  endif ()
  # stderr is a pipe, not a terminal: start and end lines, no "\r" redraws (vtkaoProgram.h).
  string(ASCII 13 cr)
  string(FIND "${err}" "${cr}" cr_at)
  if (NOT err MATCHES "baking \\.\\.\\.\n" OR NOT err MATCHES "baking done \\(100%\\)" OR
      NOT cr_at EQUAL -1)
    message(SEND_ERROR "no start and end progress lines (or a terminal bar) on stderr: '${err}'")
    math(EXPR failures "${failures} + 1")
  endif ()
  if (NOT stdout MATCHES "sattler.*vertex-directions/s")
    message(SEND_ERROR "no throughput in the summary: '${stdout}'")
    math(EXPR failures "${failures} + 1")
  endif ()
  message(STATUS "ok: sattler bake: ${stdout}")
endif ()

execute_process(COMMAND "${VTKAO}" render "${WORK}/baked.vtp" --method baked --ao-only
  --size 64x48 --output "${WORK}/baked.exr"
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/baked.exr" OR NOT stdout MATCHES "used the stored AmbientOcclusion")
  message(SEND_ERROR "render --method baked of the baked file: rc=${rc}, stdout='${stdout}', stderr='${err}'")
  math(EXPR failures "${failures} + 1")
else ()
  message(STATUS "ok: render --method baked shows the stored array")
endif ()
if (failures)
  message(FATAL_ERROR "${failures} sattler bake case(s) misbehaved")
endif ()
