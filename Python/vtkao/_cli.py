"""The `vtkao` console command: runs the program installed inside the package."""
import os
import sys


def main():
    program = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", "vtkao")
    os.execv(program, [program] + sys.argv[1:])
