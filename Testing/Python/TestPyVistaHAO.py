"""vtkao's pip package with PyPI's vtk and PyVista, in one process (off-screen, headless).

1. vtkmodules: a pass made by vtkao on a renderer made with vtkmodules renders, and darkens
   the ground where a sphere rests on it (contact), relative to the same view without it.
2. PyVista: vtkao.pyvista.enable_hao(plotter) darkens the contact; with HAO off there is none.
3. PyVista: a wall outside the view darkens the ground next to it with HAO, and not with
   PyVista's enable_ssao() (screen space cannot see what is not on screen).
Every check compares one render with another pixel by pixel (ratio of the two images on
chosen ground points), so lighting differences between points cancel.
   python TestPyVistaHAO.py [--no-ao]   (--no-ao: HAO is not enabled; the test must fail)
"""
import sys

import numpy as np
import pyvista as pv
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
from vtkmodules.util.numpy_support import vtk_to_numpy

import vtkao
import vtkao.pyvista

NO_AO = "--no-ao" in sys.argv
W, H = 320, 240
CAMERA = [(0.0, -4.0, 2.0), (0.0, 0.0, 0.3), (0.0, 0.0, 1.0)]
WALL = (2.0, 2.4, -3.0, 0.8, 0.0, 3.0)  # xmin, xmax, ymin, ymax, zmin, zmax
failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def pixel(renderer, image, point):
    """The grey level of image (rows top to bottom) at the projection of a world point."""
    renderer.SetWorldPoint(*point, 1.0)
    renderer.WorldToDisplay()
    x, y, _ = renderer.GetDisplayPoint()
    row, col = image.shape[0] - 1 - int(round(y)), int(round(x))
    patch = image[row - 1:row + 2, col - 1:col + 2, :3].astype(float)
    return patch.mean()


def ratio(renderer, with_ao, without, point):
    return pixel(renderer, with_ao, point) / max(pixel(renderer, without, point), 1.0)


# 1. Plain vtkmodules.
def vtk_scene():
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for source in (vtkPlaneSource(), vtkSphereSource()):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
        if isinstance(source, vtkPlaneSource):
            source.SetOrigin(-3, -3, 0), source.SetPoint1(3, -3, 0), source.SetPoint2(-3, 3, 0)
            source.SetResolution(60, 60)
        else:
            source.SetRadius(0.5), source.SetCenter(0, 0, 0.5)
            source.SetThetaResolution(64), source.SetPhiResolution(32)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*CAMERA[0]), camera.SetFocalPoint(*CAMERA[1]), camera.SetViewUp(*CAMERA[2])
    renderer.ResetCameraClippingRange()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(W, H)
    window.AddRenderer(renderer)
    return renderer, window


def grab(window):
    window.Render()
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    grabber.ReadFrontBufferOff()
    grabber.Update()
    image = grabber.GetOutput()
    w, h, _ = image.GetDimensions()
    array = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return array[::-1]  # rows top to bottom, like a screenshot


renderer, window = vtk_scene()
plain = grab(window)
if not NO_AO:
    hao = vtkao.enable_hao(renderer)
    check(vtkao.is_hao_pass(renderer.GetPass()), "the vtkmodules renderer holds vtkao's pass")
    check(vtkao.get_parameters(hao)["radius"] >= 0, "the pass's parameters read back")
    # The presets (ApplyPreset): applied before the other keywords, which override them.
    probe = vtkao.hybrid_ambient_occlusion_pass(preset="interactive", number_of_rays=4)
    got = vtkao.get_parameters(probe)
    check(got["voxel_resolution"] == 256 and got["voxelization_axes"] == 1 and
          not got["refinement"] and got["number_of_rays"] == 4 and got["cell_erosion"] == 0,
          "preset='interactive' sets its parameters, a later keyword overrides one")
    vtkao.set_parameters(probe, preset="quality")
    got = vtkao.get_parameters(probe)
    check(got["ao_scale"] == 2 and got["number_of_rays"] == 16 and got["refinement"] and
          got["cell_erosion"] == 0.25 and got["cells_per_radius"] == 192 and
          got["refinement_contrast"] == 0.05, "preset='quality' sets its parameters")
    check(got["refinement_list"], "the refined pixels are listed by default")
    vtkao.set_parameters(probe, refinement_rays=32, refinement_filter_radius=0,
                         refinement_list=False)
    got = vtkao.get_parameters(probe)
    check(got["refinement_rays"] == 32 and got["refinement_filter_radius"] == 0 and
          not got["refinement_list"],
          "the refinement's rays, filter radius and list are set and read back")
    try:
        vtkao.set_parameters(probe, preset="fastest")
        check(False, "an unknown preset raises ValueError")
    except ValueError:
        check(True, "an unknown preset raises ValueError")
with_hao = grab(window)
near, far = (0.55, 0.0, 0.0), (-1.2, 0.5, 0.0)  # beside the contact; open ground
print(f"vtkmodules: built with VTK {vtkao.built_with_vtk()}; "
      f"ratio near contact {ratio(renderer, with_hao, plain, near):.3f}, far "
      f"{ratio(renderer, with_hao, plain, far):.3f}")
check(ratio(renderer, with_hao, plain, near) < 0.9, "vtkmodules: HAO darkens the contact")
check(ratio(renderer, with_hao, plain, far) > 0.95, "vtkmodules: HAO leaves open ground lit")
del renderer, window


# 2. and 3. PyVista.
def plotter_scene(wall):
    plotter = pv.Plotter(off_screen=True, window_size=(W, H))
    plotter.set_background("white")
    plotter.add_mesh(pv.Plane(i_size=6, j_size=6, i_resolution=60, j_resolution=60),
                     color="white")
    plotter.add_mesh(pv.Sphere(radius=0.5, center=(0, 0, 0.5)), color="white")
    if wall:
        # A tall wall just beyond the right border of the view.
        plotter.add_mesh(pv.Box(bounds=WALL), color="white")
    plotter.camera_position = [(0.0, -4.0, 2.0), (0.0, 0.0, 0.3), (0.0, 0.0, 1.0)]
    plotter.camera.view_angle = 30.0
    plotter.renderer.ResetCameraClippingRange()
    return plotter


def shot(wall, mode, **parameters):
    plotter = plotter_scene(wall)
    if mode == "hao" and not NO_AO:
        vtkao.pyvista.enable_hao(plotter, **parameters)
    elif mode == "ssao":
        plotter.enable_ssao(radius=1.0, bias=0.005, kernel_size=64)
    image = plotter.screenshot(return_img=True)
    renderer = plotter.renderer
    return plotter, renderer, image


p0, r0, plain = shot(False, "none")
p1, r1, hao_img = shot(False, "hao")
c_near, c_far = ratio(r1, hao_img, plain, near), ratio(r1, hao_img, plain, far)
print(f"pyvista contact: ratio near {c_near:.3f}, far {c_far:.3f}")
check(c_near < 0.9, "pyvista: HAO darkens the contact")
check(c_far > 0.95, "pyvista: HAO leaves open ground lit")

# Every corner of the wall projects right of the view; the ground beside it is on screen.
beside = (1.6, 0.6, 0.0)
corners = []
for x in WALL[0:2]:
    for y in WALL[2:4]:
        for z in WALL[4:6]:
            r1.SetWorldPoint(x, y, z, 1.0), r1.WorldToDisplay()
            corners.append(r1.GetDisplayPoint()[0])
wall_x = min(corners)
check(wall_x > W, f"pyvista: the wall is outside the view (leftmost corner at x={wall_x:.0f})")
r1.SetWorldPoint(*beside, 1.0), r1.WorldToDisplay()
check(0 <= r1.GetDisplayPoint()[0] < W, "pyvista: the ground beside the wall is in view")
pw0, rw0, wall_plain = shot(True, "none")
# A radius of 2 (the parameters pass through) reaches the wall from the visible ground.
pw1, rw1, wall_hao = shot(True, "hao", radius=2.0)
pn1, rn1, nowall_hao = shot(False, "hao", radius=2.0)
pw2, rw2, wall_ssao = shot(True, "ssao")
_, _, nowall_ssao = shot(False, "ssao")
hao_beside = ratio(rw1, wall_hao, wall_plain, beside) / ratio(rn1, nowall_hao, plain, beside)
ssao_beside = pixel(rw2, wall_ssao, beside) / max(pixel(rw2, nowall_ssao, beside), 1.0)
print(f"off-screen wall: HAO darkening beside it {hao_beside:.3f}, SSAO {ssao_beside:.3f}")
check(hao_beside < 0.95, "pyvista: HAO sees the wall outside the view")
check(ssao_beside > 0.98, "pyvista: enable_ssao() does not see it (the reason for HAO)")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
