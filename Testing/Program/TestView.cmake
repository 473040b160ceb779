# vtkao view under Xvfb, driven by --script: switches methods and parameters through the
# interactor's key events, takes two screenshots (p, numbered in the working directory), prints
# the keys (?) and quits (q) with exit code 0.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${VTKAO}" view --size 480x270 --script "? s o h o + ] } I V v p n p q"
  WORKING_DIRECTORY "${WORK}" TIMEOUT 600
  RESULT_VARIABLE rc OUTPUT_VARIABLE stdout ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "view failed: rc=${rc}\n${stdout}\n${err}")
endif ()
foreach (shot vtkao-view-1.png vtkao-view-2.png)
  if (NOT EXISTS "${WORK}/${shot}")
    message(FATAL_ERROR "no screenshot ${shot}:\n${stdout}\n${err}")
  endif ()
  file(SIZE "${WORK}/${shot}" size)
  if (size LESS 1000)
    message(FATAL_ERROR "${shot} is too small (${size} bytes)")
  endif ()
endforeach ()
if (NOT stdout MATCHES "vtkao view keys:" OR NOT stdout MATCHES "wrote vtkao-view-2.png")
  message(FATAL_ERROR "missing key help or screenshot report:\n${stdout}")
endif ()
# The screenshots differ (HAO with changed parameters vs no AO).
file(SHA256 "${WORK}/vtkao-view-1.png" a)
file(SHA256 "${WORK}/vtkao-view-2.png" b)
if (a STREQUAL b)
  message(FATAL_ERROR "the two screenshots (hao, none) are identical")
endif ()
message(STATUS "ok: view\n${stdout}")
