// libFuzzer target: vtkao::AddFile, the one entry point through which `vtkao render`, `view`
// and `bake` read every input (the reader table and the glTF/OBJ importers of vtkaoScene.cxx).
// The input is written to a file with the extension of VTKAO_FUZZ_FORMAT and read as the
// program reads it; nothing is rendered and no window is opened.
//
//   VTKAO_FUZZ_FORMAT  vtp vtu vtk stl ply obj glb: the whole input is the file
//                      gltf:   input = JSON [SPLIT binary]: fuzz.gltf and fuzz.bin beside it
//                      objmtl: input = OBJ [SPLIT MTL]: fuzz.obj, whose first line is
//                              "mtllib fuzz.mtl" (so the OBJ importer runs), and fuzz.mtl
//   SPLIT is the line "@@vtkao-fuzz-split@@" (with its line breaks).
//
// Findings besides sanitizer reports and crashes: an exception other than std::runtime_error
// from AddFile, or an error message that is empty or not one line.
#include "FuzzCommon.h"

#include "vtkaoScene.h"

#include "vtkNew.h"
#include "vtkRenderer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

namespace
{
std::string Format;

const std::string Split = "\n@@vtkao-fuzz-split@@\n";

void WriteFile(const std::string& path, const char* data, size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  if (!out.good())
  {
    vtkaoFuzz::Fail("cannot write the scratch file " + path);
  }
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  const char* format = std::getenv("VTKAO_FUZZ_FORMAT");
  Format = format ? format : "";
  for (const char* known : { "vtp", "vtu", "vtk", "stl", "ply", "obj", "objmtl", "glb", "gltf" })
  {
    if (Format == known)
    {
      return 0;
    }
  }
  std::fprintf(stderr,
    "vtkaoFuzzReader: set VTKAO_FUZZ_FORMAT to vtp, vtu, vtk, stl, ply, obj, objmtl, glb or "
    "gltf\n");
  std::exit(2);
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string& dir = vtkaoFuzz::ScratchDirectory();
  const char* bytes = reinterpret_cast<const char*>(data);
  const std::string input(bytes, size);
  std::string path;
  if (Format == "objmtl" || Format == "gltf")
  {
    const size_t split = input.find(Split);
    const std::string first = input.substr(0, split);
    const std::string second =
      split == std::string::npos ? std::string() : input.substr(split + Split.size());
    if (Format == "objmtl")
    {
      path = dir + "/fuzz.obj";
      const std::string obj = "mtllib fuzz.mtl\n" + first;
      WriteFile(path, obj.data(), obj.size());
      WriteFile(dir + "/fuzz.mtl", second.data(), second.size());
    }
    else
    {
      path = dir + "/fuzz.gltf";
      WriteFile(path, first.data(), first.size());
      WriteFile(dir + "/fuzz.bin", second.data(), second.size());
    }
  }
  else
  {
    path = dir + "/fuzz." + Format;
    WriteFile(path, bytes, size);
  }

  vtkNew<vtkRenderer> renderer;
  try
  {
    vtkao::AddFile(renderer, path);
    // What `vtkao render` does next without a window: frame the camera, count triangles.
    renderer->ResetCamera();
    vtkao::CountTriangles(renderer);
  }
  catch (const std::runtime_error& e)
  {
    vtkaoFuzz::CheckMessage("read error", e.what(), false);
  }
  catch (const std::exception& e)
  {
    vtkaoFuzz::Fail(std::string("unexpected exception: ") + e.what());
  }
  vtkaoFuzz::EmptyDirectory(dir);
  return 0;
}
