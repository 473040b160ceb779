"""Hybrid Ambient Occlusion on a PyVista plotter.

    import pyvista as pv, vtkao.pyvista
    plotter = pv.Plotter(off_screen=True)
    plotter.add_mesh(pv.Sphere())
    vtkao.pyvista.enable_hao(plotter)

Unlike `plotter.enable_ssao()` (screen space), HAO sees every opaque actor of the renderer,
also those outside the view or hidden behind others.
"""
import vtkao


def enable_hao(plotter, **parameters):
    """Sets the HAO pass on the plotter's active renderer; returns the pass."""
    return vtkao.enable_hao(plotter.renderer, **parameters)


def disable_hao(plotter):
    """Removes the HAO pass from the plotter's active renderer."""
    vtkao.disable_hao(plotter.renderer)
