# Each bad invocation of `vtkao render` must print one line on stderr, exit non-zero and
# leave no output file behind.
include("${CMAKE_CURRENT_LIST_DIR}/../vtkaoCommandTest.cmake")
vtkao_test_begin()
file(WRITE "${WORK}/malformed.vtp" "<VTKFile type=\"PolyData\"> this is not a mesh")
file(WRITE "${WORK}/points.vtk" "# vtk DataFile Version 3.0\npoints\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\n")
set(cases
  "missing file|${WORK}/missing.stl"
  "malformed file|${WORK}/malformed.vtp"
  "no polygons|${WORK}/points.vtk"
  "unknown option|--frobnicate"
  "unknown method|--method magic"
  "bad number|--rays many"
  "out of range|--rays 0"
  "bad size|--size 12by7"
  "unknown format|${WORK}/malformed.xyz"
  "aov: AO scale out of range|--method aov --ao-scale 9"
  "aov: negative radius|--method aov --radius -1"
  "aov: no polygons|--method aov --ao-only ${WORK}/points.vtk")
file(WRITE "${WORK}/malformed.xyz" "1 2 3\n")
foreach (case IN LISTS cases)
  vtkao_split_case("${case}" name args)
  set(out "${WORK}/out.png")
  file(REMOVE "${out}")
  vtkao_expect_usage_error("${name}" LEFT "${out}" ARGS render ${args} --output "${out}")
endforeach ()
# An output format the program cannot write.
vtkao_expect_usage_error("bad output format" LEFT "${WORK}/out.bmp"
  ARGS render --output "${WORK}/out.bmp")
# An unwritable output directory: an error, nothing left behind.
execute_process(COMMAND "${VTKAO}" render --output "${WORK}/no/such/dir/out.png"
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if (rc EQUAL 0)
  vtkao_fail("unwritable output: rc=0")
endif ()
vtkao_test_end("bad-input")
