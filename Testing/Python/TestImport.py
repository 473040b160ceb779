"""The Python package imports from the build tree and exposes the pass with its defaults."""
import sys

from vtkao import vtkHybridAmbientOcclusionPass
import vtkao
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

hao = vtkHybridAmbientOcclusionPass()
basic = vtkRenderStepsPass()
hao.SetDelegatePass(basic)
checks = [
    (hao.GetClassName() == "vtkHybridAmbientOcclusionPass", "class name"),
    (hao.IsA("vtkImageProcessingPass") == 1, "a vtkImageProcessingPass"),
    (hao.GetDelegatePass() is basic, "delegate round trip"),
    (hao.GetNumberOfRays() == 8 and hao.GetNumberOfSteps() == 4, "defaults 8 rays, 4 steps"),
    (hao.GetVoxelResolution() == 0, "default voxel resolution 0 (automatic)"),
    (hao.WENDLAND == 0 and hao.BINARY == 1 and hao.VIEW == 1, "enums are wrapped"),
]
hao.SetNumberOfRays(0)  # clamped to [1, 1024]
checks.append((hao.GetNumberOfRays() == 1, "SetNumberOfRays clamps"))
checks.append((isinstance(vtkao.HAS_REFERENCE, bool), "HAS_REFERENCE flag"))
failed = [name for ok, name in checks if not ok]
for ok, name in checks:
    print(("ok: " if ok else "FAILED: ") + name)
print("vtkao", vtkao.__version__, "from", vtkao.__file__)
sys.exit(1 if failed else 0)
