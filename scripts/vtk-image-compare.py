#!/usr/bin/env python3
"""VTK's regression-image comparison of two PNG files, as a VTK test would make it.

    build-95/venv/bin/python scripts/vtk-image-compare.py BASELINE.png IMAGE.png [THRESHOLD]

Calls the `vtk` wheel's own vtkTesting::RegressionTest (BASELINE passed with -V, as
vtk_add_test_cxx does) once per method of VTK_TESTING_IMAGE_COMPARE_METHOD and prints the
error of each: TIGHT_VALID and LOOSE_VALID (VTK >= 9.4: SSIM in Lab space) and LEGACY_VALID
(vtkImageDifference), and whether it passes THRESHOLD (default 0.05, vtkRegressionTestImage's).
The figures of Documentation/reliability.md ("Regression images") were measured with it on
`vtkao render --size 300x300` outputs. Images that fail are written to a temporary folder
(removed at the end), never beside the baseline.
"""
import os
import sys
import tempfile

from vtkmodules.vtkCommonCore import vtkLogger
from vtkmodules.vtkTestingRendering import vtkTesting


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__.split("\n\n")[1])
    baseline, image = (os.path.abspath(p) for p in sys.argv[1:3])
    threshold = float(sys.argv[3]) if len(sys.argv) == 4 else 0.05
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
    with tempfile.TemporaryDirectory() as temporary:
        for method in ("TIGHT_VALID", "LOOSE_VALID", "LEGACY_VALID"):
            os.environ["VTK_TESTING_IMAGE_COMPARE_METHOD"] = method
            testing = vtkTesting()
            for argument in ("-V", baseline, "-T", temporary):
                testing.AddArgument(argument)
            # RegressionTest prints VTK's dashboard lines to stdout: keep them out of ours.
            sys.stdout.flush()
            saved = os.dup(1)
            with open(os.devnull, "w") as null:
                os.dup2(null.fileno(), 1)
                try:
                    result = testing.RegressionTest(image, threshold)
                finally:
                    sys.stdout.flush()
                    os.dup2(saved, 1)
                    os.close(saved)
            verdict = "passes" if result == vtkTesting.PASSED else "fails"
            error = testing.GetImageDifference()
            print(f"{method:13s} error {error:.5f}  {verdict} at {threshold}")


if __name__ == "__main__":
    main()
