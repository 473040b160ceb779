# Several scene files at once: a glTF whose one mesh is instanced by two nodes with different
# transforms (translation, scale) and an OBJ with an .mtl (two materials). Both nodes must be
# imported (2 x 12 triangles) and the OBJ's six quads triangulated (12): 36 in all, rendered
# with HAO into a PNG. Then the glTF alone, seen from +z: node 2 (translated to x = 3, scaled by 2 in y) covers
# world (3, 1.2), node 1 (at the origin, top at y = 1) does not reach (0, 1.2) but covers (0, 0.5).
include("${CMAKE_CURRENT_LIST_DIR}/../vtkaoCommandTest.cmake")
vtkao_test_begin()
set(out "${WORK}/scenes.png")
vtkao_run_or_fail("render of the imported scenes" "${out}"
  render "${SCENES}/two-boxes.gltf" "${SCENES}/ground-box.obj"
  --method hao --size 320x240 --output "${out}")
if (NOT stdout MATCHES "scene: ([0-9]+) triangles")
  message(FATAL_ERROR "no triangle count in the report:\n${stdout}")
endif ()
set(triangles "${CMAKE_MATCH_1}")
if (NOT triangles EQUAL 36)
  message(FATAL_ERROR "expected 36 triangles (2 glTF instances x 12 + 12 OBJ), got ${triangles}")
endif ()
message(STATUS "ok: ${triangles} triangles from two-boxes.gltf + ground-box.obj\n${stdout}")

if (NOT PYTHON)
  message(STATUS "no Python interpreter: transform check skipped")
  return ()
endif ()
# The transforms: 320x240, 20 degree view angle from 20 units: 34.0 pixels per unit; the
# image centre (160, 120) is world (1.5, 1).
set(out2 "${WORK}/gltf.png")
vtkao_run_or_fail("render of the glTF" "${out2}"
  render "${SCENES}/two-boxes.gltf" --method none --size 320x240
  --camera-position 1.5,1,20 --camera-focal-point 1.5,1,0 --camera-view-up 0,1,0
  --camera-view-angle 20 --output "${out2}")
execute_process(COMMAND "${PYTHON}" -c "
import sys
from vtkmodules.vtkIOImage import vtkPNGReader
r = vtkPNGReader(); r.SetFileName(sys.argv[1]); r.Update()
img = r.GetOutput(); s = img.GetPointData().GetScalars(); w = img.GetDimensions()[0]
def covered(wx, wy):  # not the white background at world (wx, wy, 0.5)
    x = int(round(160 + (wx - 1.5) * 34.0)); y = int(round(120 + (wy - 1) * 34.0))
    return sum(s.GetTuple(y * w + x)[:3]) < 3 * 240
checks = {'node 2 (translated, scaled) covers (3, 1.2)': covered(3, 1.2),
          'node 2 covers (3, -0.3)': covered(3, -0.3),
          'node 1 covers (0, 0.5)': covered(0, 0.5),
          'node 1 does not reach (0, 1.2)': not covered(0, 1.2),
          'nothing at (1.5, 0.5) between them': not covered(1.5, 0.5)}
for k, v in checks.items(): print(('ok: ' if v else 'FAILED: ') + k)
sys.exit(0 if all(checks.values()) else 1)
" "${out2}" RESULT_VARIABLE rc OUTPUT_VARIABLE pyout ERROR_VARIABLE pyerr)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "glTF node transforms not kept:\n${pyout}${pyerr}")
endif ()
message(STATUS "${pyout}")
