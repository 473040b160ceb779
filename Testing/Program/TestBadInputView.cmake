# Bad input to `vtkao render --compare` and `vtkao view`: one line on stderr, a non-zero exit,
# and no output (or temporary) file left behind.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
file(WRITE "${WORK}/broken.gltf" "{ this is not json")
file(WRITE "${WORK}/empty.gltf" "{\"asset\": {\"version\": \"2.0\"}, \"scenes\": [{\"nodes\": []}], \"scene\": 0}")
set(out "${WORK}/grid.png")
set(cases
  "compare: unknown method|render --compare none,magic --output ${out}"
  "compare: empty list|render --compare , --output ${out}"
  "compare: repeated method|render --compare hao,hao --output ${out}"
  "compare: with --method|render --compare none,hao --method hao --output ${out}"
  "compare: missing output|render --compare none,hao"
  "compare: exr output|render --compare none,hao --output ${WORK}/grid.exr"
  "compare: bad option value|render --compare none,hao --rays many --output ${out}"
  "compare: missing input|render ${WORK}/missing.stl --compare none,hao --output ${out}"
  "view: unknown option|view --frobnicate"
  "view: unknown method|view --method magic"
  "view: bad size|view --size 12by7"
  "view: bad script key|view --script \"h zz q\""
  "view: bad screenshot format|view --screenshot ${WORK}/shot.bmp"
  "view: missing input|view ${WORK}/missing.glb"
  "view: malformed gltf|view ${WORK}/broken.gltf"
  "view: gltf without polygons|view ${WORK}/empty.gltf"
  "render: malformed gltf|render ${WORK}/broken.gltf --output ${out}")
set(failures 0)
foreach (case IN LISTS cases)
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  separate_arguments(args UNIX_COMMAND "${args}")
  file(REMOVE "${out}")
  execute_process(COMMAND "${VTKAO}" ${args} TIMEOUT 120
    RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE stdout)
  string(STRIP "${err}" err)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines lines)
  file(GLOB left "${WORK}/*.png" "${WORK}/*.exr" "${WORK}/*partial*")
  if (rc EQUAL 0 OR left OR err STREQUAL "" OR lines GREATER 0)
    message(SEND_ERROR "${name}: rc=${rc}, files left='${left}', stderr='${err}'")
    math(EXPR failures "${failures} + 1")
  else ()
    message(STATUS "ok: ${name}: ${err}")
  endif ()
endforeach ()
if (failures)
  message(FATAL_ERROR "${failures} bad-input case(s) misbehaved")
endif ()
