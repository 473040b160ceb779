# Inputs that crashed `vtkao` (or made it allocate gigabytes) when fuzzing (Testing/Fuzz,
# Documentation/reliability.md): each must now give one line on stderr, exit status 1 and no
# output file. Every file with an input extension in ${CASES} (Testing/Fuzz/regressions: the
# crashes vtkao's input checks now catch) and in ${VTK_CRASH_CASES} (Testing/Fuzz/known-vtk-crashes:
# the crashes inside VTK 9.1's readers, caught by the read in a child process, or on VTK 9.5+
# by the reader itself for the formats it reads once) is one case (a case that needs a
# companion file, an .mtl or a .bin, sits with it in a folder of its own). The valid inputs
# in ${ACCEPTED} (Testing/Fuzz/accepted), shaped like the regressions, must render.
#   cmake -DVTKAO=<vtkao> -DCASES=<dir> [-DVTK_CRASH_CASES=<dir>] [-DACCEPTED=<dir>] -DWORK=<dir>
#         -P TestFuzzRegressions.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
function (inputs_in dir variable)
  set(found "")
  if (dir)
    file(GLOB_RECURSE found "${dir}/*.vtp" "${dir}/*.vtu" "${dir}/*.vtk" "${dir}/*.stl"
      "${dir}/*.ply" "${dir}/*.obj" "${dir}/*.glb" "${dir}/*.gltf")
    list(SORT found)
  endif ()
  set(${variable} ${${variable}} ${found} PARENT_SCOPE)
endfunction ()
set(inputs "")
inputs_in("${CASES}" inputs)
inputs_in("${VTK_CRASH_CASES}" inputs)
set(accepted "")
inputs_in("${ACCEPTED}" accepted)
list(LENGTH inputs count)
if (count EQUAL 0)
  message(FATAL_ERROR "no regression inputs in ${CASES} ${VTK_CRASH_CASES}")
endif ()
set(out "${WORK}/out.png")
set(failures 0)
# Inputs that VTK 9.4+'s readers read into valid data (measured with 9.5.0): there vtkao may
# render them (exit 0, an image) as well as reject them; what no VTK may do is crash.
#   vtk-point-id-out-of-range.vtk: 9.5's legacy reader stops at the malformed CONNECTIVITY and
#   keeps 20 valid triangles; 9.1's kept point ids beyond the points.
set(read_by_newer_vtk vtk-point-id-out-of-range.vtk)
# Formats read once, without the forked pre-read, when built against VTK 9.5+ (ReaderMayCrash in
# Examples/vtkao/vtkaoScene.cxx: their 9.5 readers survived the fuzz corpus). Their inputs here
# must then be rejected by the reader or the checks in the one process: the pre-read's message
# ("the VTK reader crashed on it") must not appear.
set(read_once_extensions "")
if (VTK_VERSION VERSION_GREATER_EQUAL 9.5)
  set(read_once_extensions .stl)
endif ()
set(read_once_checked 0)
foreach (input IN LISTS inputs)
  file(REMOVE "${out}")
  execute_process(COMMAND "${VTKAO}" render "${input}" --method none --size 32x32
      --output "${out}" TIMEOUT 120
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  string(STRIP "${err}" err)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines lines)
  get_filename_component(name "${input}" NAME)
  if (VTK_VERSION VERSION_GREATER_EQUAL 9.4 AND name IN_LIST read_by_newer_vtk AND
      rc STREQUAL "0" AND EXISTS "${out}")
    message(STATUS "ok: ${input}: read into valid data by VTK ${VTK_VERSION} and rendered")
    continue ()
  endif ()
  # An .obj with an .mtl beside it goes through the OBJ importer, which keeps the pre-read.
  get_filename_component(ext "${input}" LAST_EXT)
  get_filename_component(folder "${input}" DIRECTORY)
  file(GLOB materials "${folder}/*.mtl")
  set(read_once FALSE)
  if (ext IN_LIST read_once_extensions AND NOT (ext STREQUAL ".obj" AND materials))
    set(read_once TRUE)
  endif ()
  # A crash shows as a signal name, a timeout as a message: only a plain 1 is a clean failure.
  if (NOT rc STREQUAL "1" OR EXISTS "${out}" OR NOT err MATCHES "^vtkao: " OR lines GREATER 0)
    message(SEND_ERROR "${input}: rc=${rc}, stderr='${err}'")
    math(EXPR failures "${failures} + 1")
  elseif (read_once AND err MATCHES "the VTK reader crashed on it")
    message(SEND_ERROR "${input}: read in a child process first, which VTK ${VTK_VERSION} "
      "should not need for ${ext}: '${err}'")
    math(EXPR failures "${failures} + 1")
  else ()
    if (read_once)
      math(EXPR read_once_checked "${read_once_checked} + 1")
    endif ()
    message(STATUS "ok: ${input}: ${err}")
  endif ()
endforeach ()
foreach (input IN LISTS accepted)
  file(REMOVE "${out}")
  execute_process(COMMAND "${VTKAO}" render "${input}" --method none --size 32x32
      --output "${out}" TIMEOUT 120
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  string(STRIP "${err}" err)
  if (NOT rc STREQUAL "0" OR NOT EXISTS "${out}")
    message(SEND_ERROR "valid ${input} not read: rc=${rc}, stderr='${err}'")
    math(EXPR failures "${failures} + 1")
  else ()
    message(STATUS "ok (read): ${input}")
  endif ()
endforeach ()
list(LENGTH accepted valid)
if (failures)
  message(FATAL_ERROR
    "${failures} of ${count} regression and ${valid} valid fuzz input(s) misbehaved")
endif ()
if (read_once_extensions AND read_once_checked EQUAL 0)
  message(FATAL_ERROR "no input of ${read_once_extensions} was checked without the pre-read")
endif ()
message(STATUS "${count} fuzz regression inputs rejected cleanly (${read_once_checked} of them "
  "read once, without the pre-read), ${valid} valid inputs read")
