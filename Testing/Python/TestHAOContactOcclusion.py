"""HAO from Python: a unit sphere resting on a ground plane, seen from above (400x400).
Asserts on A itself (GetAmbientOcclusionImage, float A and coverage per pixel): the ground right
beside the contact is darker than open ground by more than 0.08 (analytic: about 0.13), open
ground and the sphere's top keep A > 0.95; and the composited colour image is darker beside the
contact than the same render without the pass, and unchanged on open ground."""
import sys

import vtkao  # noqa: F401  (loads the OpenGL factory overrides first)
from vtkao import vtkHybridAmbientOcclusionPass
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def add(renderer, source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)


renderer = vtkRenderer()
renderer.SetBackground(1, 1, 1)
ground = vtkPlaneSource()
ground.SetOrigin(-5, 0, -5)
ground.SetPoint1(-5, 0, 5)
ground.SetPoint2(5, 0, -5)
add(renderer, ground)
sphere = vtkSphereSource()
sphere.SetCenter(0, 1, 0)
sphere.SetRadius(1)
sphere.SetThetaResolution(48)
sphere.SetPhiResolution(24)
add(renderer, sphere)
camera = renderer.GetActiveCamera()
camera.SetFocalPoint(0, 0, 0)
camera.SetPosition(0, 12, 0)
camera.SetViewUp(0, 0, -1)
camera.SetViewAngle(40)
renderer.ResetCameraClippingRange()

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(400, 400)
window.AddRenderer(renderer)


def grey(box):
    """Mean grey level (0-255) of the window's colour image over the pixel box."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    scalars = image.GetPointData().GetScalars()
    width = image.GetDimensions()[0]
    x0, y0, x1, y1 = box
    total, n = 0.0, 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            rgb = scalars.GetTuple(y * width + x)
            total += sum(rgb[:3]) / 3.0
            n += 1
    return total / n


def mean_ao(pass_, box):
    """Mean A over the covered pixels of the box (vtk arrays; no numpy needed)."""
    image = vtkImageData()
    if not pass_.GetAmbientOcclusionImage(image):
        return -1.0
    a = image.GetPointData().GetScalars()
    check(a.GetNumberOfComponents() == 2, "the AO image has two components (A, coverage)")
    width = image.GetDimensions()[0]
    x0, y0, x1, y1 = box
    total, n = 0.0, 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            value, coverage = a.GetTuple2(y * width + x)
            if coverage > 0.5:
                total += value
                n += 1
    return total / n if n else -1.0


# 45.8 pixels per unit on the ground; the sphere's silhouette ends ~50 px from the centre.
RING = (254, 195, 262, 205)
OPEN = (15, 15, 45, 45)
TOP = (195, 195, 205, 205)

window.Render()
plain_ring, plain_open = grey(RING), grey(OPEN)

hao = vtkHybridAmbientOcclusionPass()
hao.SetDelegatePass(vtkRenderStepsPass())
hao.SetRadius(2.0)
renderer.SetPass(hao)
window.Render()
check(hao.GetLastFrameHadOcclusion(), "the pass applied occlusion")
ring, open_, top = mean_ao(hao, RING), mean_ao(hao, OPEN), mean_ao(hao, TOP)
print("A: ring beside the contact %.3f, open ground %.3f, sphere top %.3f" % (ring, open_, top))
check(open_ > 0.95, "open ground keeps A > 0.95")
check(top > 0.95, "the top of the sphere keeps A > 0.95")
check(0.0 <= ring < open_ - 0.08, "ground beside the contact is darker by more than 0.08")

hao_ring, hao_open = grey(RING), grey(OPEN)
print("grey: ring %.1f -> %.1f, open %.1f -> %.1f" % (plain_ring, hao_ring, plain_open, hao_open))
check(hao_ring < plain_ring - 10, "the composited image is darker beside the contact")
check(abs(hao_open - plain_open) < 4, "open ground looks the same with and without the pass")

renderer.ReleaseGraphicsResources(window)
sys.exit(1 if failures else 0)
