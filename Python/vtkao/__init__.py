"""vtkao for PyPI's vtk: Hybrid Ambient Occlusion on any vtkmodules (or PyVista) renderer.

    import vtkao
    hao = vtkao.enable_hao(renderer, radius=0.5)     # renderer: a vtkmodules vtkRenderer
    vtkao.set_parameters(hao, number_of_rays=32)

`vtkao.pyvista.enable_hao(plotter)` does the same for a PyVista plotter. The program
`vtkao` (render, bench, quality, view, bake) is installed as a console command.
"""
# The wrapped base classes must be registered before a pass is handed to Python.
import vtkmodules.vtkRenderingCore  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from ._vtkao import (  # noqa: F401
    built_with_vtk,
    get_parameters,
    hybrid_ambient_occlusion_pass,
    is_hao_pass,
    set_parameters,
)

# Values of the `falloff` and `region_mode` parameters.
WENDLAND, BINARY = 0, 1
SCENE, VIEW, EXPLICIT = 0, 1, 2


def enable_hao(renderer, **parameters):
    """Render `renderer` with Hybrid Ambient Occlusion; returns the pass (see set_parameters)."""
    hao = hybrid_ambient_occlusion_pass(**parameters)
    renderer.SetPass(hao)
    return hao


def disable_hao(renderer):
    """Back to VTK's default rendering (no pass) when the renderer's pass is vtkao's."""
    if renderer.GetPass() is not None and is_hao_pass(renderer.GetPass()):
        renderer.SetPass(None)
