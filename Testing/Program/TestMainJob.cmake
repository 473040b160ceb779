# The README's main job at a small size: `vtkao render --method hao --frames N --orbit D
# --timings T --output P` writes the PNG and a timings file with one entry per frame.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${VTKAO}" render --method hao --size 160x90 --frames 3 --orbit 2
    --timings "${WORK}/hao-timings.json" --output "${WORK}/hao.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "rc=${rc}\n${out}${err}")
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "the main job failed (rc=${rc}): ${err}")
endif ()
foreach (f hao.png hao-timings.json)
  if (NOT EXISTS "${WORK}/${f}")
    message(FATAL_ERROR "the main job wrote no ${f}")
  endif ()
endforeach ()
file(READ "${WORK}/hao-timings.json" timings)
string(JSON frames ERROR_VARIABLE json_error LENGTH "${timings}" frames)
if (json_error OR NOT frames EQUAL 3)
  message(FATAL_ERROR "hao-timings.json does not hold 3 frames (${frames} ${json_error}): ${timings}")
endif ()
