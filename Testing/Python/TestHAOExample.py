"""Runs Examples/Python/hao_example.py (argv[1]) writing argv[2]; asserts the PNG exists, has
the example's size (640x480) and is not blank."""
import os
import runpy
import sys

from vtkmodules.vtkIOImage import vtkPNGReader

example, output = sys.argv[1], sys.argv[2]
if os.path.exists(output):
    os.remove(output)
sys.argv = [example, output]
runpy.run_path(example, run_name="__main__")
if not os.path.exists(output):
    print("FAILED: the example wrote no", output)
    sys.exit(1)
reader = vtkPNGReader()
reader.SetFileName(output)
reader.Update()
dims = reader.GetOutput().GetDimensions()
print("image", dims)
if dims[:2] != (640, 480):
    print("FAILED: expected 640x480")
    sys.exit(1)
# Not blank: more than one grey level.
scalars = reader.GetOutput().GetPointData().GetScalars()
levels = {int(sum(scalars.GetTuple(i)[:3])) for i in range(0, scalars.GetNumberOfTuples(), 97)}
if len(levels) < 10:
    print("FAILED: the image is (nearly) blank:", len(levels), "levels")
    sys.exit(1)
print("ok: %s written, %d grey levels sampled" % (output, len(levels)))
