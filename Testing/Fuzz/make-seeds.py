#!/usr/bin/env python3
"""Write the seed corpora of the vtkao fuzz targets (Testing/Fuzz/seeds/<target>/).

Small valid inputs: command lines for the option parsers (arguments separated by NUL bytes) and
files of every format AddFile reads, written by VTK's own writers where it has one (Debian's
python3-vtk9) so the readers see what VTK produces: ASCII, binary, appended, compressed.
Usage: /usr/bin/python3 Testing/Fuzz/make-seeds.py [OUTPUT_DIR]   (default: Testing/Fuzz/seeds)
"""
import base64
import json
import os
import shutil
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "seeds")
SCENES = os.path.join(HERE, "..", "Data", "Scenes")
SPLIT = b"\n@@vtkao-fuzz-split@@\n"  # FuzzReader.cxx


def write(target, name, data):
    d = os.path.join(OUT, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def command_lines():
    lines = {
        "render": [
            "--output\0out.png",
            "in.vtp\0--method\0ssao\0--size\0320x240\0--output\0out.exr",
            "--method\0hao\0--ao-only\0--radius\00.5\0--bias\00.01\0--spread\00.5\0--falloff\0none"
            "\0--rays\064\0--steps\016\0--voxel-resolution\0512\0--voxel-axes\03\0--ao-scale\04"
            "\0--filter-size\08\0--no-filter\0--intensity\01.5\0--region\0view\0--output\0a.exr",
            "--camera-position\01,2,3\0--camera-focal-point\00,0,0\0--camera-view-up\00,1,0"
            "\0--camera-view-angle\045\0--frames\03\0--orbit\010\0--timings\0t.json\0--output\0o.png",
            "--method\0reference\0--samples\016\0--scene-triangles\0100000\0--output\0r.png",
            "--method\0baked\0--ssao-kernel\064\0--output\0b.png",
        ],
        "compare": [
            "--compare\0none,ssao,hao\0--output\0grid.png",
            "--compare\0none,hao\0--size\016x12\0--output\0grid.png",
            "--compare\0hao,ssao,none,reference\0--size\08x8\0--rays\08\0--output\0g.png",
            "--size\032x16\0--compare\0none\0--ao-only\0--output\0g.png",
        ],
        "bake": [
            "in.vtp\0--output\0out.vtp",
            "in.stl\0--output\0out.vtp\0--samples\064\0--radius\02\0--bias\00.01\0--spread\00.5"
            "\0--falloff\0none\0--method\0raycast",
            "in.ply\0--output\0out.vtp\0--method\0sattler\0--samples\0128",
            "in.obj\0--output\0out.vtp\0--method\0hemisphere\0--resolution\032",
        ],
        "view": [
            "in.vtp\0--method\0ssao\0--size\0640x480",
            "--screenshot\0s.png\0--samples\016\0--script\0h s n o + - ] [ } { I i V v p ? c q",
            "a.glb\0b.obj\0--method\0reference\0--size\01x1",
        ],
        "bench": [
            "--quick",
            "--frames\05\0--size\0320x180\0--output-json\0b.json\0--output-md\0b.md",
        ],
        "quality": [
            "--quick\0--output-dir\0q",
            "--size\064x64\0--samples\016\0--scenes\0contact,offscreen\0--methods\0none,ssao,hao,aov"
            "\0--falloff\0none\0--bias\00.01\0--rays\016\0--steps\04\0--voxel-resolution\064",
            "--voxel-axes\03\0--ao-scale\04\0--filter-size\08\0--no-filter\0--region\0view"
            "\0--ssao-kernel\016\0--reference-cache\0c\0--label\0x\0--no-images"
            "\0--max-hao-rmse\00.1\0--max-hao-ssao-ratio\00.5\0--methods\0hao,ssao",
        ],
    }
    for target, cases in lines.items():
        for i, c in enumerate(cases):
            write(target, "seed-%d" % i, c)


def vtk_files():
    from vtkmodules.vtkCommonCore import vtkPoints, vtkFloatArray, vtkUnsignedCharArray
    from vtkmodules.vtkCommonDataModel import (vtkUnstructuredGrid, vtkCellArray, VTK_TETRA,
                                               VTK_HEXAHEDRON, VTK_WEDGE, VTK_TRIANGLE, VTK_QUAD,
                                               vtkStructuredPoints, vtkRectilinearGrid,
                                               vtkStructuredGrid, vtkPolyData)
    from vtkmodules.vtkFiltersSources import vtkSphereSource, vtkCubeSource
    from vtkmodules.vtkFiltersCore import vtkTriangleFilter, vtkPolyDataNormals, vtkElevationFilter
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLUnstructuredGridWriter
    from vtkmodules.vtkIOLegacy import (vtkPolyDataWriter, vtkUnstructuredGridWriter,
                                        vtkStructuredPointsWriter, vtkRectilinearGridWriter,
                                        vtkStructuredGridWriter)
    from vtkmodules.vtkIOGeometry import vtkSTLWriter, vtkOBJWriter
    from vtkmodules.vtkIOPLY import vtkPLYWriter

    tmp = os.path.join(OUT, ".tmp")
    os.makedirs(tmp, exist_ok=True)

    def run(writer, data, name, **settings):
        path = os.path.join(tmp, name)
        writer.SetFileName(path)
        writer.SetInputData(data)
        for k, v in settings.items():
            getattr(writer, k)(*v) if isinstance(v, tuple) else getattr(writer, k)()
        writer.Write()
        with open(path, "rb") as f:
            return f.read()

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(5)
    sphere.SetPhiResolution(4)
    elevation = vtkElevationFilter()
    elevation.SetInputConnection(sphere.GetOutputPort())
    elevation.Update()
    mesh = vtkPolyData()
    mesh.DeepCopy(elevation.GetOutput())  # points, polys, normals, a scalar array

    # A few volumetric cells: a hexahedron, a tetrahedron and a wedge sharing points.
    ug = vtkUnstructuredGrid()
    pts = vtkPoints()
    for p in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1),
              (0, 1, 1), (0.5, 0.5, 2), (2, 0, 0), (2, 1, 0)]:
        pts.InsertNextPoint(p)
    ug.SetPoints(pts)
    ug.InsertNextCell(VTK_HEXAHEDRON, 8, list(range(8)))
    ug.InsertNextCell(VTK_TETRA, 4, [4, 5, 6, 8])
    ug.InsertNextCell(VTK_WEDGE, 6, [1, 9, 2, 5, 10, 6])
    ug.InsertNextCell(VTK_TRIANGLE, 3, [0, 1, 4])
    temperature = vtkFloatArray()
    temperature.SetName("T")
    for i in range(ug.GetNumberOfPoints()):
        temperature.InsertNextValue(i)
    ug.GetPointData().SetScalars(temperature)

    # .vtp and .vtu: ASCII, binary inline, appended raw, appended zlib / lz4 / lzma.
    for fmt, data, writer_type in (("vtp", mesh, vtkXMLPolyDataWriter),
                                   ("vtu", ug, vtkXMLUnstructuredGridWriter)):
        variants = {
            "ascii": dict(SetDataModeToAscii=()),
            "binary": dict(SetDataModeToBinary=(), SetCompressorTypeToNone=()),
            "appended-raw": dict(SetDataModeToAppended=(), EncodeAppendedDataOff=(),
                                 SetCompressorTypeToNone=()),
            "appended-zlib": dict(SetDataModeToAppended=(), EncodeAppendedDataOn=(),
                                  SetCompressorTypeToZLib=()),
            "binary-lz4": dict(SetDataModeToBinary=(), SetCompressorTypeToLZ4=()),
            "binary-lzma-uint32": dict(SetDataModeToBinary=(), SetCompressorTypeToLZMA=(),
                                       SetHeaderTypeToUInt32=()),
        }
        for name, settings in variants.items():
            write(fmt, name + "." + fmt, run(writer_type(), data, "x." + fmt, **settings))

    # Legacy .vtk: polydata (5.1 and 4.2 layouts, ASCII and binary), an unstructured grid,
    # structured points, a rectilinear and a structured grid (all become surfaces in AddFile).
    for version in (51, 42):
        for binary in (False, True):
            w = vtkPolyDataWriter()
            w.SetFileVersion(version)
            if binary:
                w.SetFileTypeToBinary()
            write("vtk", "polydata-%d-%s.vtk" % (version, "bin" if binary else "ascii"),
                  run(w, mesh, "x.vtk"))
    write("vtk", "ugrid.vtk", run(vtkUnstructuredGridWriter(), ug, "x.vtk"))
    w = vtkUnstructuredGridWriter()
    w.SetFileVersion(42)
    w.SetFileTypeToBinary()
    write("vtk", "ugrid-42-bin.vtk", run(w, ug, "x.vtk"))
    sp = vtkStructuredPoints()
    sp.SetDimensions(3, 2, 2)
    sp.SetSpacing(0.5, 1, 1)
    write("vtk", "spoints.vtk", run(vtkStructuredPointsWriter(), sp, "x.vtk"))
    rg = vtkRectilinearGrid()
    rg.SetDimensions(2, 3, 1)
    for setter, values in ((rg.SetXCoordinates, [0, 1]), (rg.SetYCoordinates, [0, 1, 3]),
                           (rg.SetZCoordinates, [0])):
        a = vtkFloatArray()
        for v in values:
            a.InsertNextValue(v)
        setter(a)
    write("vtk", "rgrid.vtk", run(vtkRectilinearGridWriter(), rg, "x.vtk"))
    sg = vtkStructuredGrid()
    sg.SetDimensions(2, 2, 1)
    sgp = vtkPoints()
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0.5)]:
        sgp.InsertNextPoint(p)
    sg.SetPoints(sgp)
    write("vtk", "sgrid.vtk", run(vtkStructuredGridWriter(), sg, "x.vtk"))
    write("vtk", "strips.vtk",
          "# vtk DataFile Version 3.0\nstrips\nASCII\nDATASET POLYDATA\nPOINTS 5 float\n"
          "0 0 0 1 0 0 0 1 0 1 1 0 0 2 0\nTRIANGLE_STRIPS 1 6\n5 0 1 2 3 4\n"
          "LINES 1 3\n2 0 4\nVERTICES 1 2\n1 3\nPOINT_DATA 5\nSCALARS s float 1\n"
          "LOOKUP_TABLE default\n0 1 2 3 4\nNORMALS n float\n0 0 1 0 0 1 0 0 1 0 0 1 0 0 1\n"
          "FIELD f 1\nids 1 5 int\n0 1 2 3 4\n")

    # .stl: ASCII and binary; .ply: ASCII, binary little and big endian, with colours.
    cube = vtkCubeSource()
    tri = vtkTriangleFilter()
    tri.SetInputConnection(cube.GetOutputPort())
    tri.Update()
    cube_mesh = tri.GetOutput()
    write("stl", "ascii.stl", run(vtkSTLWriter(), cube_mesh, "x.stl", SetFileTypeToASCII=()))
    write("stl", "binary.stl", run(vtkSTLWriter(), cube_mesh, "x.stl", SetFileTypeToBinary=()))
    colored = vtkPolyData()
    colored.DeepCopy(cube_mesh)
    rgb = vtkUnsignedCharArray()
    rgb.SetName("RGB")
    rgb.SetNumberOfComponents(3)
    for i in range(colored.GetNumberOfPoints()):
        rgb.InsertNextTuple3(10 * i, 255 - 10 * i, 128)
    colored.GetPointData().SetScalars(rgb)
    for name, settings in (("ascii", dict(SetFileTypeToASCII=())),
                           ("binary-le", dict(SetFileTypeToBinary=(), SetDataByteOrderToLittleEndian=())),
                           ("binary-be", dict(SetFileTypeToBinary=(), SetDataByteOrderToBigEndian=()))):
        w = vtkPLYWriter()
        w.SetArrayName("RGB")
        write("ply", name + ".ply", run(w, colored, "x.ply", **settings))
    write("ply", "quads-texcoords.ply",
          "ply\nformat ascii 1.0\ncomment by hand\nelement vertex 4\nproperty float x\n"
          "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
          "property float nz\nproperty float u\nproperty float v\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n0 0 0 0 0 1 0 0\n"
          "1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n0 1 0 0 0 1 0 1\n4 0 1 2 3\n")

    # .obj: VTK's writer (v, vn, f v//vn) and one by hand (vt, groups, lines, negative indices).
    write("obj", "writer.obj", run(vtkOBJWriter(), mesh, "x.obj"))
    write("obj", "hand.obj",
          "# by hand\no quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
          "vt 0 1\nvn 0 0 1\ng front\nf 1/1/1 2/2/1 3/3/1 4/4/1\ng back\nf -1 -2 -3\nl 1 3\np 2\n")
    shutil.rmtree(tmp)


def scenes():
    # .obj + .mtl: the test scene of Testing/Data/Scenes (FuzzReader adds the mtllib line) and
    # one with a texture map and the other material statements.
    with open(os.path.join(SCENES, "ground-box.obj"), "rb") as f:
        obj = b"".join(l for l in f.readlines() if not l.startswith(b"mtllib"))
    with open(os.path.join(SCENES, "ground-box.mtl"), "rb") as f:
        mtl = f.read()
    write("objmtl", "ground-box", obj + SPLIT + mtl)
    write("objmtl", "textured",
          b"v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\nusemtl tex\n"
          b"f 1/1/1 2/2/1 3/3/1\n" + SPLIT +
          b"newmtl tex\nKa 0.1 0.1 0.1\nKd 0.5 0.5 0.5\nKs 1 1 1\nNs 10\nd 0.9\nillum 2\n"
          b"map_Kd missing.png\n")

    # glTF: the test scene (buffer as a data: URI), the same with the buffer in fuzz.bin beside
    # it (FuzzReader writes the part after the split there), and .glb packings of it.
    with open(os.path.join(SCENES, "two-boxes.gltf"), "rb") as f:
        gltf = f.read()
    write("gltf", "two-boxes-data-uri.gltf", gltf)
    doc = json.loads(gltf)
    uri = doc["buffers"][0]["uri"]
    binary = base64.b64decode(uri.split(",", 1)[1])
    external = json.loads(gltf)
    external["buffers"][0]["uri"] = "fuzz.bin"
    write("gltf", "two-boxes-external", json.dumps(external).encode() + SPLIT + binary)
    # A matrix node, a child node, a camera and a light (KHR_lights_punctual).
    fancy = json.loads(gltf)
    fancy["buffers"][0]["uri"] = "fuzz.bin"
    fancy["nodes"].append({"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1],
                           "children": [0], "camera": 0})
    fancy["nodes"].append({"rotation": [0, 0.7071, 0, 0.7071], "extensions":
                           {"KHR_lights_punctual": {"light": 0}}})
    fancy["scenes"][0]["nodes"] = [1, 2, 3]
    fancy["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
    fancy["extensionsUsed"] = ["KHR_lights_punctual"]
    fancy["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}
    write("gltf", "nodes-camera-light", json.dumps(fancy).encode() + SPLIT + binary)

    def glb(document, payload):
        js = json.dumps(document).encode()
        js += b" " * (-len(js) % 4)
        payload += b"\0" * (-len(payload) % 4)
        chunks = struct.pack("<II", len(js), 0x4E4F534A) + js
        chunks += struct.pack("<II", len(payload), 0x004E4942) + payload
        return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks

    embedded = json.loads(gltf)
    del embedded["buffers"][0]["uri"]
    write("glb", "two-boxes.glb", glb(embedded, binary))
    fancy_glb = json.loads(json.dumps(fancy))
    del fancy_glb["buffers"][0]["uri"]
    write("glb", "nodes-camera-light.glb", glb(fancy_glb, binary))


if __name__ == "__main__":
    if os.path.isdir(OUT):
        shutil.rmtree(OUT)
    command_lines()
    vtk_files()
    scenes()
    total = sum(len(files) for _, _, files in os.walk(OUT))
    print("wrote %d seeds to %s" % (total, OUT))
