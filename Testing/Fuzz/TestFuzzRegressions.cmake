# Inputs that crashed `vtkao` (or made it allocate gigabytes) when fuzzing (Testing/Fuzz,
# Documentation/reliability.md): each must now give one line on stderr, exit status 1 and no
# output file. Every file with an input extension in ${CASES} (Testing/Fuzz/regressions: the
# crashes vtkao's input checks now catch) and in ${VTK_CRASH_CASES} (Testing/Fuzz/known-vtk-crashes:
# the crashes inside VTK 9.1's readers, caught by the read in a child process) is one case (a case
# that needs a companion file, an .mtl or a .bin, sits with it in a folder of its own). The
# valid inputs in ${ACCEPTED} (Testing/Fuzz/accepted), shaped like the regressions, must render.
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
  # A crash shows as a signal name, a timeout as a message: only a plain 1 is a clean failure.
  if (NOT rc STREQUAL "1" OR EXISTS "${out}" OR NOT err MATCHES "^vtkao: " OR lines GREATER 0)
    message(SEND_ERROR "${input}: rc=${rc}, stderr='${err}'")
    math(EXPR failures "${failures} + 1")
  else ()
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
message(STATUS "${count} fuzz regression inputs rejected cleanly, ${valid} valid inputs read")
