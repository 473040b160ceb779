"""The Embree reference module (built with the project when Embree was found) imports and runs:
the vertex baker gives A = 1 (no occlusion) on the outside of a lone sphere, and keeps the API it
inherits from vtkAOBaker (ports, Bias, ArrayName)."""
import sys

import vtkao
from vtkao import vtkAOReferenceRenderer, vtkAOVertexBaker
from vtkmodules.vtkFiltersSources import vtkSphereSource

if not vtkao.HAS_REFERENCE:
    print("FAILED: vtkao.HAS_REFERENCE is False in a build with the reference module")
    sys.exit(1)
print("ok:", vtkAOReferenceRenderer().GetClassName(), vtkAOVertexBaker().GetClassName())

sphere = vtkSphereSource()
sphere.SetThetaResolution(16)
sphere.SetPhiResolution(8)
baker = vtkAOVertexBaker()
if not isinstance(baker, vtkao.vtkAOBaker):
    print("FAILED: vtkAOVertexBaker does not derive from vtkAOBaker")
    sys.exit(1)
for method in ("AddOccluderConnection", "AddOccluderData", "RemoveAllOccluders", "SetBias",
               "GetBias", "SetArrayName", "GetArrayName", "GetEffectiveBias", "SetRadius",
               "SetSpread", "SetFalloffToBinary", "SetSamples", "SetSeed", "GetNumberOfRays"):
    if not hasattr(baker, method):
        print("FAILED: vtkAOVertexBaker has no", method)
        sys.exit(1)
baker.SetInputConnection(sphere.GetOutputPort())
baker.SetSamples(16)
baker.Update()
out = baker.GetOutput()
ao = out.GetPointData().GetArray(baker.GetArrayName())
if ao is None or ao.GetNumberOfTuples() != out.GetNumberOfPoints():
    print("FAILED: the baker added no per-vertex AO array")
    sys.exit(1)
lo, hi = ao.GetRange()
print("A on a lone convex sphere: [%.3f, %.3f]" % (lo, hi))
if lo < 0.99:
    print("FAILED: a convex sphere occludes itself (min A %.3f)" % lo)
    sys.exit(1)
print("ok: baked A = 1 on a convex sphere")
