# vtkao render --compare: the grid has one panel per method (one row for <= 3), the right size,
# labels, and no temporary panel files are left beside it.
include("${CMAKE_CURRENT_LIST_DIR}/../vtkaoCommandTest.cmake")
vtkao_test_begin()
set(out "${WORK}/grid.png")
vtkao_run_or_fail(compare "${out}"
  render --compare none,ssao,hao --size 320x180 --output "${out}")
if (NOT stdout MATCHES "wrote .*grid.png \\(3 panels: none,ssao,hao, 320x180 each\\)")
  message(FATAL_ERROR "unexpected report: ${stdout}")
endif ()
# PNG header: width and height (big-endian) at bytes 16..23.
file(READ "${out}" header LIMIT 24 HEX)
string(SUBSTRING "${header}" 32 8 w)
string(SUBSTRING "${header}" 40 8 h)
math(EXPR w "0x${w}")
math(EXPR h "0x${h}")
if (NOT w EQUAL 968 OR NOT h EQUAL 180) # 3 x 320 + 2 gaps of 4
  message(FATAL_ERROR "grid is ${w}x${h}, expected 968x180")
endif ()
file(GLOB leftovers "${WORK}/*compare-*" "${WORK}/*.partial*")
if (leftovers)
  message(FATAL_ERROR "temporary files left: ${leftovers}")
endif ()
# The panels are different images: no AO vs HAO differ (the check reads the PNG with VTK).
if (PYTHON)
  execute_process(COMMAND "${PYTHON}" -c "
import sys
from vtkmodules.vtkIOImage import vtkPNGReader
r = vtkPNGReader(); r.SetFileName(sys.argv[1]); r.Update()
img = r.GetOutput(); s = img.GetPointData().GetScalars(); w = img.GetDimensions()[0]
def mean(x0):  # mean grey of the lower half of the panel starting at column x0
    t = n = 0
    for y in range(0, 80, 2):
        for x in range(x0 + 20, x0 + 300, 2):
            t += sum(s.GetTuple(y * w + x)[:3]); n += 3
    return t / n
none, ssao, hao = mean(0), mean(324), mean(648)
print('mean grey: none %.1f ssao %.1f hao %.1f' % (none, ssao, hao))
sys.exit(0 if hao < none - 1.0 else 1)
" "${out}" RESULT_VARIABLE rc OUTPUT_VARIABLE pyout ERROR_VARIABLE pyerr)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "the HAO panel is not darker than the no-AO panel: ${pyout}${pyerr}")
  endif ()
  message(STATUS "${pyout}")
endif ()
message(STATUS "ok: ${stdout}")
