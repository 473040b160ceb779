"""Summarize render_ranks.py --benchmark output (JSON lines of AOBENCH) as a Markdown table:
per ranks and grid, the median (and min) over re-voxelizations of the grid read-back, the wait
for the other ranks, the AllReduce (bitwise OR) and the upload, in ms; the first sample (the
first frames' extra work) is left out. "reduction total" is read-back + AllReduce + upload
(the wait is load imbalance between the ranks, not the reduction's cost). "sent MB" is what
rank 0 put into the AllReduces: the sparse reduction moves one bit per chunk of 16 voxel
columns, then only the chunks some rank occupies. The voxelization column is the GPU time of
rank 0's previous voxelization, for scale."""
import json
import statistics
import sys

COLUMNS = [(3, "read-back"), (4, "wait"), (5, "AllReduce"), (6, "upload")]
print("| ranks | grid (cells) | grid MB | sent MB | " + " | ".join(
    "%s ms median (min)" % name for _, name in COLUMNS) +
    " | reduction total ms (median) | voxelization GPU ms (median) |")
print("|---|---|---|---|" + "---|" * len(COLUMNS) + "---|---|")
for line in open(sys.argv[1]):
    line = line.strip()
    if not line:
        continue
    d = json.loads(line)
    samples = d["samples"][1:] or d["samples"]
    dims = "x".join(str(int(v)) for v in samples[0][9:12])
    mb = samples[0][2] / 1e6
    sent = statistics.median(s[12] for s in samples) / 1e6 if len(samples[0]) > 12 else mb
    cells = []
    for index, _ in COLUMNS:
        values = [s[index] for s in samples]
        cells.append("%.2f (%.2f)" % (statistics.median(values), min(values)))
    total = statistics.median(s[3] + s[5] + s[6] for s in samples)
    voxelize = statistics.median(s[7] for s in samples)
    print("| %d | %s | %.2f | %.2f | %s | %.2f | %.1f |" % (d["ranks"], dims, mb, sent,
                                                           " | ".join(cells), total, voxelize))
