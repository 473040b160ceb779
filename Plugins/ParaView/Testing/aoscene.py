"""Shared scene and image helpers for the ParaView plugin tests (pvpython and pvbatch).

The scene: a 4 x 4 plane at z = 0 with a box, a sphere and a cylinder resting on it. A
programmable source gives each MPI rank its own part: the plane on rank 0, the objects on
ranks 1..N-1 (round robin), everything on rank 0 when there is one rank. So the receiver (the
plane) and its occluders (the objects) live on different ranks.
"""
import os
import sys

from paraview import simple

PLUGIN_ENV = "VTKAO_PARAVIEW_PLUGIN"
SIZE = (480, 320)

# Samples on the plane (world x, y at z = 0): next to each object's base, and open plane far
# from every object. A at the contact is well below 1; on the open plane it is 1.
CONTACT_POINTS = [(-0.8, -0.47), (0.85, 0.02), (0.0, 1.03)]
OPEN_POINTS = [(-1.5, -1.4), (1.5, -1.4), (0.0, -1.4)]

SOURCE_SCRIPT = r"""
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.vtkFiltersSources import (vtkPlaneSource, vtkCubeSource, vtkSphereSource,
                                          vtkCylinderSource)
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkCommonTransforms import vtkTransform

info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER()) if info.Has(sddp.UPDATE_PIECE_NUMBER()) else 0
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES()) if info.Has(sddp.UPDATE_NUMBER_OF_PIECES()) else 1

plane = vtkPlaneSource()
plane.SetOrigin(-2, -2, 0); plane.SetPoint1(2, -2, 0); plane.SetPoint2(-2, 2, 0)
plane.SetResolution(8, 8)
box = vtkCubeSource()
box.SetCenter(-0.8, 0.0, 0.4); box.SetXLength(0.8); box.SetYLength(0.8); box.SetZLength(0.8)
sphere = vtkSphereSource()
sphere.SetCenter(0.85, 0.5, 0.5); sphere.SetRadius(0.5)
sphere.SetThetaResolution(48); sphere.SetPhiResolution(24)
cylinder = vtkCylinderSource()  # axis along y: stand it up along z
cylinder.SetRadius(0.3); cylinder.SetHeight(1.2); cylinder.SetResolution(48); cylinder.CappingOn()
t = vtkTransform(); t.Translate(0.0, 1.4, 0.6); t.RotateX(90)
standing = vtkTransformPolyDataFilter(); standing.SetTransform(t)
standing.SetInputConnection(cylinder.GetOutputPort())
parts = [plane, box, sphere, standing]

def owner(i):
    if pieces <= 1 or i == 0:
        return 0
    return 1 + (i - 1) % (pieces - 1)

append = vtkAppendPolyData()
mine = [p for i, p in enumerate(parts) if owner(i) == piece]
for p in mine:
    tri = vtkTriangleFilter(); tri.SetInputConnection(p.GetOutputPort()); tri.Update()
    append.AddInputData(tri.GetOutput())
if mine:
    append.Update()
    self.GetPolyDataOutput().ShallowCopy(append.GetOutput())
"""

INFO_SCRIPT = r"""
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm
self.GetOutputInformation(0).Set(vtkAlgorithm.CAN_HANDLE_PIECE_REQUEST(), 1)
"""


def load_plugin():
    path = os.environ.get(PLUGIN_ENV)
    if not path or not os.path.exists(path):
        print("set %s to AmbientOcclusionView.so (scripts/setup-paraview.sh prints it)" % PLUGIN_ENV)
        finish(2)
    simple.LoadPlugin(path, remote=False, ns=globals())
    return path


def make_source():
    src = simple.ProgrammableSource()
    src.OutputDataSetType = "vtkPolyData"
    src.Script = SOURCE_SCRIPT
    src.ScriptRequestInformation = INFO_SCRIPT
    return src


def setup_view(view, source):
    simple._DisableFirstRenderCameraReset()
    view.ViewSize = list(SIZE)
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    display = simple.Show(source, view)
    display.Representation = "Surface"
    display.AmbientColor = [1.0, 1.0, 1.0]
    display.DiffuseColor = [1.0, 1.0, 1.0]
    view.CameraPosition = [0.0, -5.2, 3.6]
    view.CameraFocalPoint = [0.0, 0.1, 0.3]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    view.CameraParallelProjection = 0
    return display


def set_hao(view, ao_only=True, reduction=True):
    view.AmbientOcclusionMethod = "HAO"
    view.AmbientOcclusionRadius = 0.5
    view.AmbientOcclusionRays = 32
    view.AmbientOcclusionSteps = 8
    view.AmbientOcclusionVoxelResolution = 128
    view.AmbientOcclusionRegionMode = "Scene"
    view.AmbientOcclusionExplicitRegion = [-2.5, 2.5, -2.5, 2.5, -0.5, 2.0]
    view.AmbientOcclusionIntensity = 1.0
    view.AmbientOcclusionFalloff = "Wendland"
    view.AmbientOcclusionFilterSize = 16
    view.AmbientOcclusionOnly = 1 if ao_only else 0
    view.AmbientOcclusionParallelReduction = 1 if reduction else 0


def save(view, path):
    simple.Render(view)
    simple.SaveScreenshot(path, view, ImageResolution=list(SIZE), TransparentBackground=0)


def read_gray(path):
    """The PNG as a numpy array of grey values in [0, 1] (rows from the top)."""
    import numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return numpy.flipud(a.astype(numpy.float64).mean(axis=2) / 255.0)


def project(view, x, y, z=0.0):
    """Pixel (column, row from the top) of a world point for the view's camera."""
    from vtkmodules.vtkRenderingCore import vtkCoordinate
    ren = view.GetRenderer()
    c = vtkCoordinate()
    c.SetCoordinateSystemToWorld()
    c.SetValue(x, y, z)
    col, row = c.GetComputedDoubleDisplayValue(ren)
    return int(round(col)), int(round(SIZE[1] - 1 - row))


def window_mean(gray, pixel, half=3):
    col, row = pixel
    return float(gray[row - half:row + half + 1, col - half:col + half + 1].mean())


def rmse(a, b):
    import numpy
    return float(numpy.sqrt(((a - b) ** 2).mean()))


def finish(code):
    """End a pvpython/pvbatch script with @p code. ParaView 5.11 (Debian) crashes with SIGSEGV
    when a script calls sys.exit(), even without plugins: leave through os._exit instead."""
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
