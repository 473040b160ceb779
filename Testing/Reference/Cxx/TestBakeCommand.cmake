# `vtkao bake` and the ray-traced render methods from the command line:
# - bad input prints one line on stderr, exits non-zero and leaves no file;
# - a good bake writes a .vtp with an AmbientOcclusion array, a progress bar on stderr;
# - `render --method reference|baked --ao-only` write an image.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/malformed.vtp" "<VTKFile type=\"PolyData\"> this is not a mesh")
# Two triangles: a floor (y = 0) and, above it, a ceiling (y = 0.5), in one legacy file.
file(WRITE "${WORK}/mesh.vtk" "# vtk DataFile Version 3.0\nmesh\nASCII\nDATASET POLYDATA\n"
  "POINTS 8 float\n-1 0 -1  -1 0 1  1 0 1  1 0 -1  -3 0.5 -3  -3 0.5 3  3 0.5 3  3 0.5 -3\n"
  "POLYGONS 2 10\n4 0 1 2 3\n4 4 5 6 7\n")
set(failures 0)
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
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  separate_arguments(args UNIX_COMMAND "${args}")
  file(GLOB leftovers "${WORK}/out*")
  if (leftovers)
    file(REMOVE ${leftovers})
  endif ()
  execute_process(COMMAND "${VTKAO}" bake ${args}
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  string(STRIP "${err}" err)
  file(GLOB leftovers "${WORK}/out*" "${WORK}/no/such/dir/*")
  if (rc EQUAL 0 OR leftovers OR err STREQUAL "" OR err MATCHES "\n")
    message(SEND_ERROR "${name}: rc=${rc}, files left='${leftovers}', stderr='${err}'")
    math(EXPR failures "${failures} + 1")
  else ()
    message(STATUS "ok: ${name}: ${err}")
  endif ()
endforeach ()

# A good bake: binary falloff, R = 1, the floor's corners under the ceiling at 0.5 R get
# A = (H/R)^2 = 0.25 (written as ASCII-free binary VTP: check the array name and the file).
execute_process(COMMAND "${VTKAO}" bake "${WORK}/mesh.vtk" --output "${WORK}/baked.vtp"
  --samples 256 --radius 1 --bias 1e-5 --falloff none
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
file(GLOB partial "${WORK}/*.partial*")
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/baked.vtp" OR partial)
  message(SEND_ERROR "good bake failed: rc=${rc}, partial='${partial}', stderr='${err}'")
  math(EXPR failures "${failures} + 1")
else ()
  file(READ "${WORK}/baked.vtp" vtp)
  if (NOT vtp MATCHES "Name=\"AmbientOcclusion\"" OR NOT vtp MATCHES "RangeMin=\"0\\.2[45]")
    message(SEND_ERROR "baked.vtp lacks the AmbientOcclusion array or its minimum is not 0.25")
    math(EXPR failures "${failures} + 1")
  endif ()
  # stderr is a pipe here, not a terminal: the progress shows as a start and an end line,
  # without the terminal's "\r" redraws (vtkaoProgram.h).
  string(ASCII 13 cr)
  string(FIND "${err}" "${cr}" cr_at)
  if (NOT err MATCHES "baking \\.\\.\\.\n" OR NOT err MATCHES "baking done \\(100%\\)" OR
      NOT cr_at EQUAL -1)
    message(SEND_ERROR "no start and end progress lines (or a terminal bar) on stderr: '${err}'")
    math(EXPR failures "${failures} + 1")
  endif ()
  message(STATUS "ok: good bake: ${stdout}")
endif ()

# The render methods write their images.
foreach (method reference baked)
  execute_process(COMMAND "${VTKAO}" render "${WORK}/mesh.vtk" --method ${method} --ao-only
    --samples 16 --size 64x48 --output "${WORK}/${method}.exr"
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/${method}.exr")
    message(SEND_ERROR "render --method ${method} failed: rc=${rc}, stderr='${err}'")
    math(EXPR failures "${failures} + 1")
  else ()
    message(STATUS "ok: render --method ${method}")
  endif ()
endforeach ()
if (failures)
  message(FATAL_ERROR "${failures} bake/reference command case(s) misbehaved")
endif ()
