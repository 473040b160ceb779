# `vtkao bake` and the ray-traced render methods from the command line:
# - bad input prints one line on stderr, exits non-zero and leaves no file;
# - a good bake writes a .vtp with an AmbientOcclusion array, a progress bar on stderr;
# - `render --method reference|baked --ao-only` write an image.
include("${CMAKE_CURRENT_LIST_DIR}/../../vtkaoCommandTest.cmake")
vtkao_test_begin()
file(WRITE "${WORK}/malformed.vtp" "<VTKFile type=\"PolyData\"> this is not a mesh")
vtkao_write_floor_and_ceiling()
set(cases
  "missing input|${WORK}/missing.stl --output ${WORK}/out.vtp"
  "malformed input|${WORK}/malformed.vtp --output ${WORK}/out.vtp"
  "no input|--output ${WORK}/out.vtp"
  "no output|${WORK}/mesh.vtk"
  "wrong output format|${WORK}/mesh.vtk --output ${WORK}/out.png"
  "unknown option|${WORK}/mesh.vtk --frobnicate --output ${WORK}/out.vtp"
  "bad samples|${WORK}/mesh.vtk --samples 0 --output ${WORK}/out.vtp"
  "unknown bake method|${WORK}/mesh.vtk --method magic --output ${WORK}/out.vtp"
  "unwritable output|${WORK}/mesh.vtk --output ${WORK}/no/such/dir/out.vtp")
foreach (case IN LISTS cases)
  vtkao_split_case("${case}" name args)
  file(GLOB leftovers "${WORK}/out*")
  if (leftovers)
    file(REMOVE ${leftovers})
  endif ()
  vtkao_expect_usage_error("${name}" LEFT "${WORK}/out*" "${WORK}/no/such/dir/*" ARGS bake ${args})
endforeach ()

# A good bake: binary falloff, R = 1, the floor's corners under the ceiling at 0.5 R get
# A = (H/R)^2 = 0.25 (written as ASCII-free binary VTP: check the array name and the file).
execute_process(COMMAND "${VTKAO}" bake "${WORK}/mesh.vtk" --output "${WORK}/baked.vtp"
  --samples 256 --radius 1 --bias 1e-5 --falloff none
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
file(GLOB partial "${WORK}/*.partial*")
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/baked.vtp" OR partial)
  vtkao_fail("good bake failed: rc=${rc}, partial='${partial}', stderr='${err}'")
else ()
  file(READ "${WORK}/baked.vtp" vtp)
  if (NOT vtp MATCHES "Name=\"AmbientOcclusion\"" OR NOT vtp MATCHES "RangeMin=\"0\\.2[45]")
    vtkao_fail("baked.vtp lacks the AmbientOcclusion array or its minimum is not 0.25")
  endif ()
  vtkao_check_progress_lines("" "${err}")
  message(STATUS "ok: good bake: ${stdout}")
endif ()

# The render methods write their images.
foreach (method reference baked)
  execute_process(COMMAND "${VTKAO}" render "${WORK}/mesh.vtk" --method ${method} --ao-only
    --samples 16 --size 64x48 --output "${WORK}/${method}.exr"
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/${method}.exr")
    vtkao_fail("render --method ${method} failed: rc=${rc}, stderr='${err}'")
  else ()
    message(STATUS "ok: render --method ${method}")
  endif ()
endforeach ()
vtkao_test_end("bake/reference command")
