# `vtkao bake --method sattler` and `vtkao render --method baked` on the baked file:
# - a floor (y = 0, half-width 1) under a ceiling (y = 0.5, half-width 3): with R = infinity the
#   floor corners see only the gaps beside the ceiling, A = 1 - F = 0.0317 (F: the point-to-
#   rectangle form factors of the four ceiling parts); the ceiling (normal +y) is open, A = 1;
# - a progress bar on stderr; the summary reports vertex-directions per second;
# - an unknown bake method fails with one line and no file;
# - `render baked.vtp --method baked --ao-only` uses the stored array (no re-bake).
include("${CMAKE_CURRENT_LIST_DIR}/../../vtkaoCommandTest.cmake")
vtkao_test_begin()
vtkao_write_floor_and_ceiling()

vtkao_expect_usage_error("unknown bake method" LEFT "${WORK}/bad.vtp"
  ARGS bake "${WORK}/mesh.vtk" --method hemicube --output "${WORK}/bad.vtp")

execute_process(COMMAND "${VTKAO}" bake "${WORK}/mesh.vtk" --method sattler --samples 1024
  --bias 1e-4 --output "${WORK}/baked.vtp"
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
file(GLOB partial "${WORK}/*.partial*")
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/baked.vtp" OR partial)
  vtkao_fail("sattler bake failed: rc=${rc}, partial='${partial}', stderr='${err}'")
else ()
  vtkao_read_ao_range("${WORK}/baked.vtp" lo hi)
  message(STATUS "A range: ${lo} .. ${hi} (expected 0.0317 .. 1)")
  if (lo STREQUAL "" OR lo LESS 0.0217 OR lo GREATER 0.0417 OR hi LESS 0.99)
    vtkao_fail("baked.vtp: A in [${lo}, ${hi}], expected [0.0317 +- 0.01, 1]")
  endif ()
  vtkao_check_progress_lines("" "${err}")
  if (NOT stdout MATCHES "sattler.*vertex-directions/s")
    vtkao_fail("no throughput in the summary: '${stdout}'")
  endif ()
  message(STATUS "ok: sattler bake: ${stdout}")
endif ()

execute_process(COMMAND "${VTKAO}" render "${WORK}/baked.vtp" --method baked --ao-only
  --size 64x48 --output "${WORK}/baked.exr"
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/baked.exr" OR NOT stdout MATCHES "used the stored AmbientOcclusion")
  vtkao_fail("render --method baked of the baked file: rc=${rc}, stdout='${stdout}', stderr='${err}'")
else ()
  message(STATUS "ok: render --method baked shows the stored array")
endif ()
vtkao_test_end("sattler bake")
