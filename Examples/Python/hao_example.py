"""Render a mesh (or a sphere on a plane) with Hybrid Ambient Occlusion to a PNG.
usage: /usr/bin/python3 hao_example.py [MESH.vtp|.stl|.ply|.obj] [OUT.png]
(PYTHONPATH=<build or prefix>/lib/python3/dist-packages)"""
import sys
from vtkao import vtkHybridAmbientOcclusionPass  # also loads VTK's OpenGL2 factory overrides
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import vtkRenderStepsPass

args = sys.argv[1:]
output = args.pop() if args and args[-1].lower().endswith(".png") else "hao.png"
if args:  # a mesh file
    readers = {"vtp": vtkXMLPolyDataReader, "stl": vtkSTLReader, "ply": vtkPLYReader,
               "obj": vtkOBJReader}
    reader = readers[args[0].rsplit(".", 1)[-1].lower()]()
    reader.SetFileName(args[0])
    sources = [reader]
else:  # a sphere resting on a plane
    sphere, plane = vtkSphereSource(), vtkPlaneSource()
    sphere.SetCenter(0, 1, 0); sphere.SetThetaResolution(64); sphere.SetPhiResolution(32)
    plane.SetOrigin(-4, 0, -4); plane.SetPoint1(-4, 0, 4); plane.SetPoint2(4, 0, -4)
    sources = [sphere, plane]
renderer = vtkRenderer()
renderer.SetBackground(1, 1, 1)
for source in sources:
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
renderer.GetActiveCamera().SetPosition(0, 4, 7)
renderer.ResetCamera()

# --- The ambient occlusion: four lines. ---
hao = vtkHybridAmbientOcclusionPass()
hao.SetDelegatePass(vtkRenderStepsPass())  # HAO wraps VTK's standard render steps
hao.SetNumberOfRays(8)                     # see Documentation/user-guide.md for the rest
renderer.SetPass(hao)

window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(640, 480)
window.AddRenderer(renderer)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetFileName(output)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print("wrote", output)
