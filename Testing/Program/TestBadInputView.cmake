# Bad input to `vtkao render --compare` and `vtkao view`: one line on stderr, a non-zero exit,
# and no output (or temporary) file left behind.
include("${CMAKE_CURRENT_LIST_DIR}/../vtkaoCommandTest.cmake")
vtkao_test_begin()
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
foreach (case IN LISTS cases)
  vtkao_split_case("${case}" name args)
  file(REMOVE "${out}")
  vtkao_expect_usage_error("${name}" TIMEOUT 120
    LEFT "${WORK}/*.png" "${WORK}/*.exr" "${WORK}/*partial*" ARGS ${args})
endforeach ()
vtkao_test_end("bad-input")
