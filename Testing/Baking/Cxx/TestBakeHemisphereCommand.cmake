# `vtkao bake --method hemisphere` on a floor (y = 0, half-width 1) under a ceiling (y = 0.5,
# half-width 3), both in the input:
# - R = infinity: the floor corners see only the gaps beside the ceiling, A = 1 - F = 0.0317
#   (F: the point-to-rectangle form factors of the four ceiling parts); the ceiling is open, A = 1;
# - --radius 1: every floor point sees the ceiling within R only for cos(theta) >= h / R, so
#   A = (h / R)^2 = 0.25 everywhere on the floor;
# - a progress bar on stderr; the summary reports vertices/s;
# - --resolution out of range, or with another method, fails with one line and no file.
include("${CMAKE_CURRENT_LIST_DIR}/../../vtkaoCommandTest.cmake")
vtkao_test_begin()
vtkao_write_floor_and_ceiling()

# One line on stderr, a non-zero exit and no output file.
function(expect_usage_error name)
  vtkao_expect_usage_error("${name}" LEFT "${WORK}/${name}.vtp"
    ARGS bake "${WORK}/mesh.vtk" ${ARGN} --output "${WORK}/${name}.vtp")
  set(failures ${failures} PARENT_SCOPE)
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
    vtkao_fail("${name}: hemisphere bake failed: rc=${rc}, partial='${partial}', stderr='${err}'")
    set(failures ${failures} PARENT_SCOPE)
    return()
  endif ()
  vtkao_check_progress_lines("${name}: " "${err}")
  if (NOT stdout MATCHES "hemisphere.*vertices/s")
    vtkao_fail("${name}: no throughput in the summary: '${stdout}'")
  endif ()
  set(failures ${failures} PARENT_SCOPE)
  message(STATUS "${name}: ${stdout}")
  vtkao_read_ao_range("${WORK}/${name}.vtp" range_lo range_hi)
  set(lo "${range_lo}" PARENT_SCOPE)
  set(hi "${range_hi}" PARENT_SCOPE)
endfunction()

bake(infinite --resolution 32 --bias 1e-4)
message(STATUS "R = infinity: A range ${lo} .. ${hi} (expected 0.0317 .. 1)")
if (lo STREQUAL "" OR lo LESS 0.0267 OR lo GREATER 0.0367 OR hi LESS 0.99)
  vtkao_fail("R = infinity: A in [${lo}, ${hi}], expected [0.0317 +- 0.005, 1]")
endif ()

bake(radius --resolution 32 --bias 1e-4 --radius 1)
message(STATUS "R = 1: A range ${lo} .. ${hi} (expected 0.25 .. 1)")
if (lo STREQUAL "" OR lo LESS 0.24 OR lo GREATER 0.26 OR hi LESS 0.99)
  vtkao_fail("R = 1: A in [${lo}, ${hi}], expected [0.25 +- 0.01, 1]")
endif ()

vtkao_test_end("hemisphere bake")
