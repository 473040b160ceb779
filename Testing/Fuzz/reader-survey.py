#!/usr/bin/env python3
"""Survey of the plain VTK readers on the fuzz corpus, without vtkao's guards (issue 15).

Every input of Testing/Fuzz (seeds, regressions, known-vtk-crashes, accepted, unhandled) is read
by the reader or importer that vtkao::AddFile (Examples/vtkao/vtkaoScene.cxx) picks for its
extension, with none of vtkao's input checks in front and no forked pre-read: each file in a
subprocess of its own, with a timeout. The outcome of each is one of

  ok       the reader finished and produced data (or finished with errors it reported)
  empty    the reader finished and produced nothing (it reported the file as unreadable)
  crash    the subprocess died by a signal (SIGSEGV, SIGABRT, ...) or an uncaught C++
           exception (std::terminate: SIGABRT)
  hang     it was still reading after the timeout

Run it with the Python whose vtkmodules are the VTK to survey:

  /usr/bin/python3 Testing/Fuzz/reader-survey.py                 # Debian 12's VTK 9.1
  build-95/venv/bin/python Testing/Fuzz/reader-survey.py         # VTK 9.5 from PyPI
      [--timeout SECONDS] [--filters] [--tsv FILE] [--only SUBSTRING]
      [--mutations N --formats stl,obj [--save DIR]]

--filters also runs what AddFile runs on the reader's output (vtkDataSetSurfaceFilter,
vtkTriangleFilter, vtkPolyDataNormals; for importers, the actors' mappers' inputs through
vtkPolyDataNormals), which vtkao guards with DataSetProblem, not with the pre-read.
The summary is a Markdown table per format on stdout; --tsv writes one line per file.
--mutations N adds N mutants (seeded, so reproducible) of each corpus file of --formats: 1-3 of
byte flips, numbers replaced by extreme ones, truncation, lines deleted or repeated; --save keeps
the mutants that crashed or hung.
"""
import argparse
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
FOLDERS = ["seeds", "regressions", "known-vtk-crashes", "accepted", "unhandled"]
EXTENSIONS = [".vtp", ".vtu", ".vtk", ".stl", ".ply", ".obj", ".glb", ".gltf"]
SPLIT = b"\n@@vtkao-fuzz-split@@\n"


def material_file(path):
    """The .mtl an .obj names with `mtllib`, if it exists beside it (vtkaoScene.cxx's rule)."""
    with open(path, "rb") as f:
        for raw in f.read().split(b"\n"):
            line = raw.decode("latin-1")
            if line.startswith("mtllib") and len(line) > 7:
                name = line[7:].rstrip(" \t\r").lstrip(" \t")
                mtl = os.path.join(os.path.dirname(path), name)
                return mtl if os.path.isfile(mtl) else ""
    return ""


def read_one(path, filters):
    """Reads @p path as AddFile would pick its reader; prints the outcome. Runs in the child."""
    from vtkmodules.vtkCommonCore import vtkObject, vtkLogger

    vtkObject.GlobalWarningDisplayOff()
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    ext = os.path.splitext(path)[1].lower()
    mtl = material_file(path) if ext == ".obj" else ""
    if ext in (".glb", ".gltf") or mtl:
        from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the window class vtkao gets)
        import vtkmodules.vtkIOImport as imp

        if mtl:
            importer = imp.vtkOBJImporter()
            importer.SetFileName(path)
            importer.SetFileNameMTL(mtl)
            importer.SetTexturePath(os.path.dirname(path) or ".")
        else:
            importer = imp.vtkGLTFImporter()
            importer.SetFileName(path)
        window = vtkRenderWindow()  # never rendered: no OpenGL context
        renderer = vtkRenderer()
        window.AddRenderer(renderer)
        importer.SetRenderWindow(window)
        importer.Update()
        actors = renderer.GetActors()
        actors.InitTraversal()
        polys = 0
        for _ in range(actors.GetNumberOfItems()):
            actor = actors.GetNextActor()
            mapper = actor.GetMapper()
            if mapper is None:
                continue
            mapper.Update()
            data = mapper.GetInput()
            if data is None:
                continue
            polys += data.GetNumberOfPolys() + data.GetNumberOfStrips()
            if filters and data.GetNumberOfPoints():
                from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

                normals = vtkPolyDataNormals()
                normals.SetInputData(data)
                normals.Update()
        print("ok" if polys else "empty", flush=True)
        return
    import vtkmodules.vtkIOXML as xml
    import vtkmodules.vtkIOLegacy as legacy
    import vtkmodules.vtkIOGeometry as geometry
    import vtkmodules.vtkIOPLY as ply

    readers = {
        ".vtp": xml.vtkXMLPolyDataReader,
        ".vtu": xml.vtkXMLUnstructuredGridReader,
        ".vtk": legacy.vtkGenericDataObjectReader,
        ".stl": geometry.vtkSTLReader,
        ".ply": ply.vtkPLYReader,
        ".obj": geometry.vtkOBJReader,
    }
    reader = readers[ext]()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutputDataObject(0)
    cells = data.GetNumberOfCells() if data is not None and data.IsA("vtkDataSet") else 0
    if filters and cells:
        from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
        from vtkmodules.vtkFiltersCore import vtkTriangleFilter, vtkPolyDataNormals

        surface = vtkDataSetSurfaceFilter()
        surface.SetInputConnection(reader.GetOutputPort())
        triangles = vtkTriangleFilter()
        triangles.SetInputConnection(surface.GetOutputPort())
        normals = vtkPolyDataNormals()
        normals.SetInputConnection(triangles.GetOutputPort())
        normals.SplittingOff()
        normals.Update()
    print("ok" if cells else "empty", flush=True)


def cases():
    """(folder, name, path or packed file, format) of every input of the corpus."""
    found = []
    for folder in FOLDERS:
        top = os.path.join(HERE, folder)
        for root, dirs, files in os.walk(top):
            dirs.sort()
            for name in sorted(files):
                path = os.path.join(root, name)
                ext = os.path.splitext(name)[1].lower()
                rel = os.path.relpath(path, HERE)
                if ext in EXTENSIONS:
                    fmt = ext[1:]
                    if ext == ".obj" and material_file(path):
                        fmt = "obj+mtl"
                    found.append((folder, rel, path, fmt, None))
                elif folder == "seeds" and os.path.basename(root) in ("gltf", "objmtl"):
                    # libFuzzer inputs of the split formats (FuzzReader.cxx): unpacked per run.
                    fmt = "gltf" if os.path.basename(root) == "gltf" else "obj+mtl"
                    found.append((folder, rel, path, fmt, os.path.basename(root)))
    return found


def unpack(path, kind, scratch):
    """A split libFuzzer input (FuzzReader.cxx) written out as files; the file to read."""
    with open(path, "rb") as f:
        data = f.read()
    first, _, second = data.partition(SPLIT)
    if kind == "objmtl":
        target = os.path.join(scratch, "fuzz.obj")
        with open(target, "wb") as f:
            f.write(b"mtllib fuzz.mtl\n" + first)
        with open(os.path.join(scratch, "fuzz.mtl"), "wb") as f:
            f.write(second)
    else:
        target = os.path.join(scratch, "fuzz.gltf")
        with open(target, "wb") as f:
            f.write(first)
        with open(os.path.join(scratch, "fuzz.bin"), "wb") as f:
            f.write(second)
    return target


EXTREMES = [b"-1", b"0", b"1", b"2147483647", b"-2147483648", b"4294967296", b"1e308", b"nan",
            b"99999999", b"-99999999"]


def mutate(data, rng):
    """1-3 random edits of @p data."""
    for _ in range(rng.randint(1, 3)):
        choice = rng.randrange(5)
        if choice == 0 and data:
            i = rng.randrange(len(data))
            data = data[:i] + bytes([rng.randrange(256)]) + data[i + 1:]
        elif choice == 1:
            numbers = list(re.finditer(rb"-?[0-9]+(\.[0-9]+)?", data))
            if numbers:
                m = rng.choice(numbers)
                data = data[:m.start()] + rng.choice(EXTREMES) + data[m.end():]
        elif choice == 2 and data:
            data = data[:rng.randrange(len(data))]
        else:
            lines = data.split(b"\n")
            i = rng.randrange(len(lines))
            if choice == 3:
                del lines[i]
            else:
                lines.insert(i, lines[i])
            data = b"\n".join(lines)
    return data


def run_one(path, timeout, filters):
    command = [sys.executable, os.path.abspath(__file__), "--one", path]
    if filters:
        command.append("--filters")
    start = time.monotonic()
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                              timeout=timeout, start_new_session=True)
    except subprocess.TimeoutExpired:
        return "hang", "timeout %gs" % timeout, time.monotonic() - start
    seconds = time.monotonic() - start
    out = done.stdout.decode(errors="replace").strip().splitlines()
    if done.returncode < 0:
        return "crash", signal.Signals(-done.returncode).name, seconds
    if done.returncode != 0:
        return "crash", "exit %d" % done.returncode, seconds
    return (out[-1] if out else "empty"), "", seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--one", help=argparse.SUPPRESS)
    parser.add_argument("--filters", action="store_true")
    parser.add_argument("--timeout", type=float, default=20)
    parser.add_argument("--tsv")
    parser.add_argument("--only", default="")
    parser.add_argument("--mutations", type=int, default=0)
    parser.add_argument("--formats", default="stl,obj")
    parser.add_argument("--save")
    args = parser.parse_args()
    if args.one:
        read_one(args.one, args.filters)
        return 0
    from vtkmodules.vtkCommonCore import vtkVersion

    version = vtkVersion.GetVTKVersion()
    rows = []
    for folder, rel, path, fmt, packed in cases():
        if args.only not in rel:
            continue
        scratch = tempfile.mkdtemp(prefix="vtkao-survey-")
        try:
            target = unpack(path, packed, scratch) if packed else path
            outcome, detail, seconds = run_one(target, args.timeout, args.filters)
        finally:
            shutil.rmtree(scratch, ignore_errors=True)
        rows.append((fmt, folder, rel, outcome, detail, seconds))
        print("%-8s %-6s %-10s %5.1fs %s" % (fmt, outcome, detail, seconds, rel),
              file=sys.stderr, flush=True)
        if args.mutations and not packed and fmt in args.formats.split(","):
            rng = random.Random(rel)
            with open(path, "rb") as f:
                original = f.read()
            for n in range(args.mutations):
                scratch = tempfile.mkdtemp(prefix="vtkao-survey-")
                try:
                    target = os.path.join(scratch, "mutant" + os.path.splitext(path)[1])
                    mutant = mutate(original, rng)
                    with open(target, "wb") as f:
                        f.write(mutant)
                    outcome, detail, seconds = run_one(target, args.timeout, args.filters)
                finally:
                    shutil.rmtree(scratch, ignore_errors=True)
                name = "%s~%d" % (rel, n)
                rows.append((fmt, "mutants", name, outcome, detail, seconds))
                if outcome in ("crash", "hang"):
                    print("%-8s %-6s %-10s %5.1fs %s" % (fmt, outcome, detail, seconds, name),
                          file=sys.stderr, flush=True)
                    if args.save:
                        os.makedirs(args.save, exist_ok=True)
                        saved = name.replace("/", "_") + os.path.splitext(path)[1]
                        with open(os.path.join(args.save, saved), "wb") as f:
                            f.write(mutant)
    if args.tsv:
        with open(args.tsv, "w") as f:
            f.write("# VTK %s%s\n" % (version, ", with filters" if args.filters else ""))
            for row in rows:
                f.write("%s\t%s\t%s\t%s\t%s\t%.1f\n" % row)
    print("VTK %s, %s, timeout %g s per file%s\n" % (
        version, sys.executable, args.timeout, ", reader + filters" if args.filters else ""))
    print("| format | files | ok | empty | crash | hang | crashed / hung on |")
    print("|---|---|---|---|---|---|---|")
    for fmt in ["vtp", "vtu", "vtk", "stl", "ply", "obj", "obj+mtl", "glb", "gltf"]:
        mine = [r for r in rows if r[0] == fmt]
        if not mine:
            continue
        count = {k: sum(1 for r in mine if r[3] == k) for k in ("ok", "empty", "crash", "hang")}
        bad = ", ".join("%s (%s)" % (r[2], r[4]) for r in mine if r[3] in ("crash", "hang"))
        print("| %s | %d | %d | %d | %d | %d | %s |" % (
            fmt, len(mine), count["ok"], count["empty"], count["crash"], count["hang"],
            bad or "-"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
