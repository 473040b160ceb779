# Progress bars redraw in place ("\r") only on a terminal: with stderr redirected (here a
# pipe, as in CI logs) a ray-traced render writes no carriage return and only a few lines.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${VTKAO}" render --method reference --size 96x54 --samples 16
    --output "${WORK}/reference.png"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "rc=${rc}\nstdout: ${out}\nstderr: ${err}")
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "vtkao render --method reference failed (rc=${rc})")
endif ()
string(ASCII 13 cr)
string(FIND "${err}" "${cr}" at)
if (NOT at EQUAL -1)
  message(FATAL_ERROR "redirected stderr holds carriage returns (a terminal progress bar)")
endif ()
string(REGEX MATCHALL "\n" newlines "${err}")
list(LENGTH newlines lines)
if (lines GREATER 4)
  message(FATAL_ERROR "redirected stderr has ${lines} lines; a few at most expected")
endif ()
if (NOT err MATCHES "tracing")
  message(FATAL_ERROR "no progress line at all on redirected stderr")
endif ()
