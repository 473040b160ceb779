"""Compare two PNGs written by render_ranks.py (pvpython or any Python with ParaView's vtk and
numpy): prints the RMSE over the whole image (grey, [0, 1]) and the mean A at the contact
samples of each, as JSON. With --max-rmse / --min-rmse, exits 1 when the RMSE is outside."""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import aoscene  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("reference")
parser.add_argument("image")
parser.add_argument("--max-rmse", type=float)
parser.add_argument("--min-rmse", type=float)
parser.add_argument("--label", default="")
args = parser.parse_args()

a = aoscene.read_gray(args.reference)
b = aoscene.read_gray(args.image)
if a.shape != b.shape:
    print("%s: size %s differs from %s" % (args.image, b.shape, a.shape))
    aoscene.finish(1)
import numpy  # noqa: E402
diff = numpy.abs(a - b)
result = {
    "label": args.label,
    "reference": os.path.basename(args.reference),
    "image": os.path.basename(args.image),
    "rmse": aoscene.rmse(a, b),
    "max_abs": float(diff.max()),
    "pixels_off_by_more_than_0.1": int((diff > 0.1).sum()),
}
print("COMPARE " + json.dumps(result))
ok = True
if args.max_rmse is not None and not result["rmse"] <= args.max_rmse:
    print("FAIL: RMSE %.4f > %.4f" % (result["rmse"], args.max_rmse))
    ok = False
if args.min_rmse is not None and not result["rmse"] >= args.min_rmse:
    print("FAIL: RMSE %.4f < %.4f" % (result["rmse"], args.min_rmse))
    ok = False
aoscene.finish(0 if ok else 1)
