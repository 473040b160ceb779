"""Hybrid Ambient Occlusion on a PyVista plotter (pip install vtkao[pyvista]).

    python pyvista_hao.py [OUTPUT.png]
"""
import sys

import pyvista as pv

import vtkao.pyvista

plotter = pv.Plotter(off_screen=True, window_size=(800, 600))
plotter.add_mesh(pv.Plane(i_size=6, j_size=6), color="white")
plotter.add_mesh(pv.Sphere(radius=0.5, center=(0, 0, 0.5)), color="white")
plotter.camera_position = [(0.0, -4.0, 2.0), (0.0, 0.0, 0.3), (0.0, 0.0, 1.0)]
vtkao.pyvista.enable_hao(plotter)  # the whole integration: one line
plotter.screenshot(sys.argv[1] if len(sys.argv) > 1 else "pyvista_hao.png")
