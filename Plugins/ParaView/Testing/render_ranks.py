"""pvbatch script: render the split scene (plane on rank 0, objects on the other ranks) and
save one PNG. Run symmetric on N ranks:

    mpiexec -np N pvbatch --symmetric render_ranks.py --method hao --ao-only --output out.png

--method hao        the plugin's view with Hybrid Ambient Occlusion (AO-only with --ao-only)
--method ssao       ParaView's render view with its built-in UseAmbientOcclusion (SSAO)
--method none       ParaView's render view, no AO
--no-reduction      HAO without combining the voxel grids across ranks (each rank alone)
--voxel-resolution  HAO grid resolution (default 128)
--background R,G,B  view background (default white; AO-only images stay white)
--accumulate N      HAO: a still averages N frames (AmbientOcclusionAccumulatedFrames); exit 1
                    unless rank 0's last render showed the mean of N frames
--benchmark N       re-voxelize N times (alternating the resolution by one cell) and print
                    the grid-reduction times of rank 0 as JSON on stdout
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import aoscene  # noqa: E402
from paraview import simple  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--method", choices=["hao", "ssao", "none"], default="hao")
parser.add_argument("--ao-only", action="store_true")
parser.add_argument("--no-reduction", action="store_true")
parser.add_argument("--voxel-resolution", type=int, default=128)
parser.add_argument("--benchmark", type=int, default=0)
parser.add_argument("--accumulate", type=int, default=0)
parser.add_argument("--output", default="")
parser.add_argument("--background", default="", help="R,G,B (pictures); default white")
args = parser.parse_args()

from paraview import servermanager  # noqa: E402
controller = servermanager.vtkProcessModule.GetProcessModule().GetGlobalController()
rank = controller.GetLocalProcessId()
ranks = controller.GetNumberOfProcesses()

source = aoscene.make_source()
if args.method == "hao":
    aoscene.load_plugin()
    view = simple.CreateView("AmbientOcclusionView")
else:
    view = simple.CreateView("RenderView")
aoscene.setup_view(view, source)
if args.background:
    view.Background = [float(v) for v in args.background.split(",")]
if args.method == "hao":
    aoscene.set_hao(view, ao_only=args.ao_only, reduction=not args.no_reduction)
    view.AmbientOcclusionVoxelResolution = args.voxel_resolution
    if args.accumulate:
        view.AmbientOcclusionAccumulatedFrames = args.accumulate
elif args.method == "ssao":
    view.UseAmbientOcclusion = 1
if args.output:
    aoscene.save(view, args.output)

if args.method == "hao":
    simple.Render(view)
    view.UpdatePropertyInformation()
    stats = list(view.GetProperty("AmbientOcclusionStatistics"))
    if rank == 0:
        print("AOSTATS " + json.dumps({"ranks": ranks, "statistics": stats}))
    if args.accumulate and stats[13] != args.accumulate:
        print("rank %d: the still holds %g accumulated frames, expected %d"
              % (rank, stats[13], args.accumulate))
        sys.exit(1)
    if args.benchmark:
        samples = []
        for i in range(args.benchmark):
            # A different grid each time: every render re-voxelizes and reduces.
            view.AmbientOcclusionVoxelResolution = args.voxel_resolution - (i % 2)
            simple.Render(view)
            view.UpdatePropertyInformation()
            s = list(view.GetProperty("AmbientOcclusionStatistics"))
            samples.append(s)
        if rank == 0:
            print("AOBENCH " + json.dumps({"ranks": ranks, "resolution": args.voxel_resolution,
                                           "samples": samples}))
