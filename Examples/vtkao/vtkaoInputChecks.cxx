// Checks of input files for vtkao::AddFile (vtkaoInputChecks.h).
#include "vtkaoInputChecks.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellTypes.h"
#include "vtkDataSet.h"
#include "vtkGenericCell.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtk_jsoncpp.h"
#include "vtksys/Base64.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#define VTKAO_HAS_FORK 1
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VTKAO_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define VTKAO_ASAN 1
#endif
#ifdef VTKAO_ASAN
// Where the sanitizers write their reports, and what they call before exiting on one
// (sanitizer/common_interface_defs.h).
extern "C" void __sanitizer_set_report_fd(void* fd);
extern "C" void __sanitizer_set_death_callback(void (*callback)(void));
#endif

namespace
{
#ifdef VTKAO_ASAN
// The number of threads of this process (Linux; 0 if unknown).
int ThreadCount()
{
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
  {
    if (line.rfind("Threads:", 0) == 0)
    {
      return std::atoi(line.c_str() + 8);
    }
  }
  return 0;
}
#endif

// The whole file as a string (inputs are read whole by the checks below).
std::string FileContents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}
}

namespace vtkao
{
//------------------------------------------------------------------------------
std::string BinarySTLProblem(const std::string& path)
{
  // VTK 9.1's binary reader tolerates a wrong triangle count ("many .stl files contain bogus
  // count"): it reads to the end of the file, but first allocates max(count, what the file
  // holds) * 3 points, as an int product that overflows. A count far beyond the file makes it
  // allocate gigabytes (or throw std::bad_alloc; found by fuzzing); a count somewhat off, as in
  // real files, is read as VTK reads it. ASCII files (decided as vtkSTLReader decides) have none.
  if (vtksys::SystemTools::DetectFileType(path.c_str()) == vtksys::SystemTools::FileTypeText)
  {
    return std::string();
  }
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const auto size = static_cast<unsigned long long>(std::max<std::streamoff>(0, in.tellg()));
  unsigned char count[4];
  if (size < 84 || !in.seekg(80) || !in.read(reinterpret_cast<char*>(count), 4))
  {
    return std::string(); // VTK reports the premature end itself
  }
  const unsigned long long declared = count[0] | (count[1] << 8) | (count[2] << 16) |
    (static_cast<unsigned long long>(count[3]) << 24);
  const unsigned long long holds = (size - 84) / 50;
  // 2^20 triangles more than the file holds: about 100 MB of needless allocation.
  const unsigned long long slack = 1ull << 20;
  if (declared > holds + slack)
  {
    return "binary STL header declares " + std::to_string(declared) +
      " triangles, the file holds " + std::to_string(holds);
  }
  return std::string();
}

// The first of @p n point ids out of [0, points), as a sentence; empty if none.
std::string PointIdsProblem(vtkIdType n, const vtkIdType* ids, vtkIdType points, const char* what)
{
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (ids[i] < 0 || ids[i] >= points)
    {
      return std::string(what) + ": point id " + std::to_string(ids[i]) + " out of range [0, " +
        std::to_string(points) + ")";
    }
  }
  return std::string();
}

// Offsets, cell sizes (at least @p least points: vtkTriangleFilter reads one point of every
// vertex cell and two of every line cell) and point ids of a cell array.
std::string CellArrayProblem(vtkCellArray* cells,
  vtkIdType points,
  const char* what,
  vtkIdType least = 0)
{
  if (!cells)
  {
    return std::string();
  }
  if (!cells->IsValid())
  {
    return std::string(what) + ": inconsistent cell offsets";
  }
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n < least)
    {
      return std::string(what) + ": a cell of " + std::to_string(n) + " points";
    }
    const std::string problem = PointIdsProblem(n, ids, points, what);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}

// The face stream of polyhedron @p id: number of faces, then per face its size and point ids.
std::string PolyhedronProblem(vtkUnstructuredGrid* grid, vtkIdType id)
{
  vtkIdTypeArray* faces = grid->GetFaces();
  vtkIdTypeArray* faceLocations = grid->GetFaceLocations();
  const vtkIdType size = faces ? faces->GetNumberOfValues() : 0;
  vtkIdType at =
    faceLocations && id < faceLocations->GetNumberOfValues() ? faceLocations->GetValue(id) : -1;
  if (at < 0 || at >= size)
  {
    return "polyhedron " + std::to_string(id) + " has no faces";
  }
  const vtkIdType count = faces->GetValue(at++);
  for (vtkIdType f = 0; f < count; ++f)
  {
    const vtkIdType facePoints = at < size ? faces->GetValue(at++) : -1;
    if (count < 0 || facePoints < 0 || facePoints > size - at)
    {
      return "polyhedron " + std::to_string(id) + ": face stream out of range";
    }
    const std::string problem =
      PointIdsProblem(facePoints, faces->GetPointer(at), grid->GetNumberOfPoints(), "faces");
    if (!problem.empty())
    {
      return problem;
    }
    at += facePoints;
  }
  return std::string();
}

// The cells of an unstructured grid: offsets and point ids, known types, fixed-size cells of
// their size, polyhedra with a face stream that fits.
std::string UnstructuredGridProblem(vtkUnstructuredGrid* grid)
{
  vtkCellArray* cells = grid->GetCells();
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return std::string();
  }
  std::string problem = CellArrayProblem(cells, grid->GetNumberOfPoints(), "cells");
  if (!problem.empty())
  {
    return problem;
  }
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (!types || types->GetNumberOfValues() != cells->GetNumberOfCells())
  {
    return "cell types do not match the cells";
  }
  // Per cell type (VTK keeps them in an unsigned char): -1 unknown, else the number of points
  // of a fixed-size cell (what a fresh cell of the type has), 0 if any.
  int fixedSize[256];
  std::fill(std::begin(fixedSize), std::end(fixedSize), -2);
  vtkNew<vtkGenericCell> cell;
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    const vtkIdType id = it->GetCurrentCellId();
    const int type = types->GetValue(id);
    const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
    if (fixedSize[type] == -2)
    {
      fixedSize[type] = -1;
      if (std::strcmp(name, "UnknownClass") != 0 && type != VTK_EMPTY_CELL)
      {
        cell->SetCellType(type);
        fixedSize[type] = static_cast<int>(cell->GetNumberOfPoints());
      }
    }
    if (fixedSize[type] < 0)
    {
      return "unknown cell type " + std::to_string(type);
    }
    if (type == VTK_POLYHEDRON)
    {
      if (!(problem = PolyhedronProblem(grid, id)).empty())
      {
        return problem;
      }
      continue;
    }
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    // Fixed-size cells must have that size.
    const vtkIdType fixed = fixedSize[type];
    const vtkIdType least = type == VTK_POLYGON || type == VTK_TRIANGLE_STRIP ? 3
      : type == VTK_POLY_LINE                                                 ? 2
                                                                              : 1;
    if (fixed > 0 ? n != fixed : n < least)
    {
      return "cell " + std::to_string(id) + " of type " + std::string(name) + " has " +
        std::to_string(n) + " points";
    }
  }
  return std::string();
}

// Structured and rectilinear grids: dimensions that match the points or coordinates.
std::string StructureProblem(vtkDataSet* data)
{
  if (auto* structured = vtkStructuredGrid::SafeDownCast(data))
  {
    int d[3];
    structured->GetDimensions(d);
    if (static_cast<long long>(d[0]) * d[1] * d[2] != data->GetNumberOfPoints())
    {
      return "structured grid dimensions do not match its points";
    }
  }
  else if (auto* rectilinear = vtkRectilinearGrid::SafeDownCast(data))
  {
    int d[3];
    rectilinear->GetDimensions(d);
    vtkDataArray* coordinates[3] = {
      rectilinear->GetXCoordinates(), rectilinear->GetYCoordinates(), rectilinear->GetZCoordinates()
    };
    for (int i = 0; i < 3; ++i)
    {
      if (!coordinates[i] || coordinates[i]->GetNumberOfTuples() < d[i])
      {
        return "rectilinear grid coordinates do not match its dimensions";
      }
    }
  }
  return std::string();
}

// Attributes: the filters copy one tuple per point and per cell.
std::string AttributesProblem(vtkDataSet* data)
{
  const vtkIdType cellCount = data->GetNumberOfCells();
  for (const auto& attributes :
    { std::make_pair(static_cast<vtkFieldData*>(data->GetPointData()), data->GetNumberOfPoints()),
      std::make_pair(static_cast<vtkFieldData*>(data->GetCellData()), cellCount) })
  {
    for (int a = 0; a < attributes.first->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = attributes.first->GetAbstractArray(a);
      if (array && array->GetNumberOfTuples() < attributes.second)
      {
        return std::string("array '") + (array->GetName() ? array->GetName() : "") + "' has " +
          std::to_string(array->GetNumberOfTuples()) + " tuples for " +
          std::to_string(attributes.second) +
          (attributes.first == data->GetPointData() ? " points" : " cells");
      }
    }
  }
  return std::string();
}

// What would make VTK's filters (vtkDataSetSurfaceFilter, vtkTriangleFilter,
// vtkPolyDataNormals) read or write out of bounds, none of which VTK 9.1's readers check (found
// by fuzzing): cell offsets that decrease or do not cover the connectivity, point ids outside
// the points, unknown cell types or cells of the wrong size, polyhedron face streams that do not
// fit, structured dimensions that do not match the points or coordinates, attribute arrays
// shorter than the points or cells. Empty if none.
std::string DataSetProblem(vtkDataSet* data)
{
  const vtkIdType points = data->GetNumberOfPoints();
  std::string problem;
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    if (!(problem = CellArrayProblem(poly->GetVerts(), points, "vertices", 1)).empty() ||
      !(problem = CellArrayProblem(poly->GetLines(), points, "lines", 2)).empty() ||
      !(problem = CellArrayProblem(poly->GetPolys(), points, "polygons")).empty() ||
      !(problem = CellArrayProblem(poly->GetStrips(), points, "strips")).empty())
    {
      return problem;
    }
  }
  else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    if (!(problem = UnstructuredGridProblem(grid)).empty())
    {
      return problem;
    }
  }
  else if (!(problem = StructureProblem(data)).empty())
  {
    return problem;
  }
  return AttributesProblem(data);
}

// VTK 9.1's OBJ reader and the OBJ importer index their vertex, texture coordinate and normal
// lists with the numbers of `f`, `l` and `p` statements without checking them (out-of-bounds
// reads and writes, found by fuzzing), and the reader reads before its line buffer on a line
// that starts with a NUL byte. Checked here as they parse them: each of v/vt/vn, 1-based or
// negative (relative to the ones read so far), must name one the file declares. Empty if fine.
std::string OBJProblem(const std::string& path)
{
  std::string text = FileContents(path);
  if (text.find('\0') != std::string::npos)
  {
    return "NUL byte in an OBJ file";
  }
  // Backslash-newline continues a statement (both parsers accept it).
  for (size_t at; (at = text.find("\\\n")) != std::string::npos;)
  {
    text.replace(at, 2, " ");
  }
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
    {
      lines.push_back(line);
    }
  }
  auto command = [](const std::string& line)
  {
    std::istringstream in(line);
    std::string word;
    in >> word;
    return word;
  };
  long long total[3] = { 0, 0, 0 }; // v, vt, vn in the whole file
  for (const auto& line : lines)
  {
    const std::string c = command(line);
    total[0] += c == "v";
    total[1] += c == "vt";
    total[2] += c == "vn";
  }
  long long seen[3] = { 0, 0, 0 };
  const char* names[3] = { "vertex", "texture coordinate", "normal" };
  int number = 0;
  for (const auto& line : lines)
  {
    ++number;
    const std::string c = command(line);
    seen[0] += c == "v";
    seen[1] += c == "vt";
    seen[2] += c == "vn";
    if (c != "f" && c != "l" && c != "p")
    {
      continue;
    }
    std::istringstream in(line);
    std::string token;
    in >> token; // the command
    while (in >> token)
    {
      // The forms the parsers try, in their order: v/vt/vn, v//vn, v/vt, v.
      int v[3];
      bool used[3] = { true, false, false };
      if (std::sscanf(token.c_str(), "%d/%d/%d", &v[0], &v[1], &v[2]) == 3)
      {
        used[1] = used[2] = true;
      }
      else if (std::sscanf(token.c_str(), "%d//%d", &v[0], &v[2]) == 2)
      {
        used[2] = true;
      }
      else if (std::sscanf(token.c_str(), "%d/%d", &v[0], &v[1]) == 2)
      {
        used[1] = true;
      }
      else if (std::sscanf(token.c_str(), "%d", &v[0]) != 1)
      {
        continue; // not an index: the parsers report it
      }
      for (int k = 0; k < 3; ++k)
      {
        const long long index = v[k] < 0 ? seen[k] + v[k] : static_cast<long long>(v[k]) - 1;
        if (used[k] && (index < 0 || index >= total[k]))
        {
          return "line " + std::to_string(number) + ": " + names[k] + " " + std::to_string(v[k]) +
            " does not exist";
        }
      }
    }
  }
  return std::string();
}

// VTK 9.1's OBJ importer (its MTL parser) applies material statements to the current material
// without checking that a `newmtl` came first (a null dereference), and copies every number after
// Ka/Kd/Ks and after the -s/-o/-mm options of a texture map into 3 (or 2) places (found by
// fuzzing). Empty if fine. (It also reads past its tokens when a map_Ka or map_Kd statement ends
// the file without a line end: AddFile hands it a copy that ends with one.)
std::string MTLProblem(const std::string& path)
{
  const std::string text = FileContents(path);
  if (text.find('\0') != std::string::npos)
  {
    return "NUL byte in an MTL file"; // the parser stops there, in the middle of a statement
  }
  std::istringstream in(text);
  static const std::set<std::string> statements = { "Ka", "Kd", "Ks", "Ns", "d", "illum" };
  auto isNumber = [](const std::string& word)
  {
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    return !word.empty() && *end == '\0';
  };
  bool material = false;
  for (std::string line; std::getline(in, line);)
  {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;)
    {
      w.push_back(word);
    }
    if (w.empty())
    {
      continue;
    }
    std::string lower = w[0];
    std::transform(
      lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    const bool map = lower == "map_ka" || lower == "map_kd";
    if (w[0] == "newmtl")
    {
      material = true;
      continue;
    }
    if (!statements.count(w[0]) && !map)
    {
      continue;
    }
    if (!material)
    {
      return "material statement '" + w[0] + "' before any newmtl";
    }
    // The numbers after a statement or an option (they are copied into a fixed array).
    for (size_t i = 0; i < w.size(); ++i)
    {
      const size_t room = w[i] == "-mm" ? 2 : 3;
      if (i == 0 || (map && (w[i] == "-s" || w[i] == "-o" || w[i] == "-mm")))
      {
        size_t numbers = 0;
        while (i + 1 + numbers < w.size() && isNumber(w[i + 1 + numbers]))
        {
          ++numbers;
        }
        if ((i > 0 || w[0][0] == 'K') && numbers > room)
        {
          return "'" + w[0] + "' with more than " + std::to_string(room) + " numbers";
        }
      }
    }
  }
  return std::string();
}

// A PLY property: a value (Count 0) or a list with a count of Count bytes.
struct PLYProperty
{
  std::string Name;
  int Count = 0; // size of the list count (0: not a list)
  int Size = 0;  // size of the value
  bool CountSigned = false, Float = false;
};

struct PLYElement
{
  std::string Name;
  long long Number = 0;
  std::vector<PLYProperty> Properties;
};

// A line split into words as vtkPLY::get_words does: it ends at a NUL byte, tabs and carriage
// returns are spaces, words are separated by spaces, and the first "vertex_index" becomes
// "vertex_indices" with the rest of the line dropped.
std::vector<std::string> PLYWords(std::string line)
{
  line = line.substr(0, line.find('\0'));
  const size_t index = line.find("vertex_index");
  if (index != std::string::npos)
  {
    line = line.substr(0, index) + "vertex_indices";
  }
  std::replace(line.begin(), line.end(), '\t', ' ');
  std::replace(line.begin(), line.end(), '\r', ' ');
  std::vector<std::string> w;
  for (size_t i = 0; i < line.size();)
  {
    const size_t end = std::min(line.find(' ', i), line.size());
    if (end > i)
    {
      w.push_back(line.substr(i, end - i));
    }
    i = end + 1;
  }
  return w;
}

// A property line's words: the property appended to the last element. Empty if fine.
std::string AddPLYProperty(const std::vector<std::string>& w, std::vector<PLYElement>& elements)
{
  // Type name -> size in bytes, signed.
  static const std::map<std::string, std::pair<int, bool>> types = { { "char", { 1, true } },
    { "int8", { 1, true } },
    { "uchar", { 1, false } },
    { "uint8", { 1, false } },
    { "short", { 2, true } },
    { "int16", { 2, true } },
    { "ushort", { 2, false } },
    { "uint16", { 2, false } },
    { "int", { 4, true } },
    { "int32", { 4, true } },
    { "uint", { 4, false } },
    { "uint32", { 4, false } },
    { "float", { 4, true } },
    { "float32", { 4, true } },
    { "double", { 8, true } },
    { "float64", { 8, true } } };
  const bool list = w.size() > 1 && w[1] == "list";
  if (elements.empty() || w.size() != (list ? 5u : 3u) || !types.count(w[list ? 3 : 1]) ||
    (list && !types.count(w[2])))
  {
    return "invalid property line";
  }
  PLYProperty p;
  p.Name = w.back();
  // VTK reads "vertex_index" as "vertex_indices".
  if (p.Name.find("vertex_index") == 0)
  {
    p.Name = "vertex_indices";
  }
  const std::string& type = w[list ? 3 : 1];
  p.Size = types.at(type).first;
  p.Float = type.find("float") == 0 || type == "double";
  if (list)
  {
    p.Count = types.at(w[2]).first;
    p.CountSigned = types.at(w[2]).second;
  }
  elements.back().Properties.push_back(p);
  return std::string();
}

// The header up to end_header: the format and the elements with their properties; @p at is
// left at the first byte of the body. Empty if fine.
std::string ParsePLYHeader(const std::string& text,
  size_t& at,
  std::string& format,
  std::vector<PLYElement>& elements)
{
  bool ended = false;
  for (int number = 0; at < text.size() && !ended; ++number)
  {
    const size_t nl = text.find('\n', at);
    std::string line = text.substr(at, nl == std::string::npos ? std::string::npos : nl - at);
    at = nl == std::string::npos ? text.size() : nl + 1;
    if (line.size() > 4000)
    {
      return "header line longer than 4000 characters";
    }
    const std::vector<std::string> w = PLYWords(line);
    if (number == 0 && (w.size() != 1 || w[0] != "ply"))
    {
      return "no 'ply' line";
    }
    if (w.empty())
    {
      // vtkPLY takes an empty line for the end of the header.
      return "empty line in the header";
    }
    if (w[0] == "format")
    {
      if (w.size() != 3 ||
        (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian"))
      {
        return "invalid format line";
      }
      format = w[1];
    }
    else if (w[0] == "element")
    {
      char* end = nullptr;
      const long long n = w.size() == 3 ? std::strtoll(w[2].c_str(), &end, 10) : -1;
      if (w.size() != 3 || *end != '\0' || n < 0 || n > 0x7fffffff)
      {
        return "invalid element line";
      }
      elements.push_back({ w[1], n, {} });
    }
    else if (w[0] == "property")
    {
      const std::string problem = AddPLYProperty(w, elements);
      if (!problem.empty())
      {
        return problem;
      }
    }
    else if (w[0] == "end_header")
    {
      ended = true;
    }
  }
  return !ended || format.empty() ? "no format line or no end_header" : std::string();
}

// What VTK needs of the elements: each with properties and declared once, a vertex element with
// x, y and z (@p vertex), faces with a vertex_indices list. Empty if fine.
std::string PLYElementsProblem(const std::vector<PLYElement>& elements, const PLYElement*& vertex)
{
  std::set<std::string> names;
  for (const auto& e : elements)
  {
    // vtkPLY frees the property list of every element, allocated only for the first property.
    if (e.Properties.empty() || !names.insert(e.Name).second)
    {
      return "element '" + e.Name + "' without properties or declared twice";
    }
  }
  vertex = nullptr;
  for (const auto& e : elements)
  {
    if (e.Name == "vertex" && !vertex)
    {
      vertex = &e;
    }
  }
  auto has = [](const PLYElement& e, const char* name, bool list)
  {
    for (const auto& p : e.Properties)
    {
      if (p.Name == name && (p.Count > 0) == list)
      {
        return true;
      }
    }
    return false;
  };
  if (!vertex || !has(*vertex, "x", false) || !has(*vertex, "y", false) ||
    !has(*vertex, "z", false))
  {
    return "no vertex element with x, y and z";
  }
  for (const auto& e : elements)
  {
    if (e.Name == "face" && !has(e, "vertex_indices", true))
    {
      return "face element without a vertex_indices list";
    }
  }
  return std::string();
}

// One binary value of @p size bytes at @p at (advanced past it). False past the end.
bool ReadPLYBinary(const std::string& text,
  size_t& at,
  bool big,
  int size,
  bool isSigned,
  bool isFloat,
  double& value)
{
  if (size > static_cast<long long>(text.size() - at))
  {
    return false;
  }
  unsigned char b[8];
  for (int i = 0; i < size; ++i)
  {
    b[i] = static_cast<unsigned char>(text[at + (big ? size - 1 - i : i)]);
  }
  at += size;
  unsigned long long u = 0;
  for (int i = size - 1; i >= 0; --i)
  {
    u = u << 8 | b[i];
  }
  if (isFloat)
  {
    if (size == 4)
    {
      float f;
      const auto u32 = static_cast<uint32_t>(u);
      std::memcpy(&f, &u32, 4);
      value = f;
    }
    else
    {
      std::memcpy(&value, &u, 8);
    }
  }
  else if (isSigned)
  {
    const int shift = 64 - 8 * size;
    value = static_cast<double>(static_cast<long long>(u << shift) >> shift);
  }
  else
  {
    value = static_cast<double>(u);
  }
  return true;
}

// The body from @p at: every element (ASCII lines or binary values) against the header; faces
// have at most 256 indices, each naming one of @p vertices. Empty if fine.
std::string PLYBodyProblem(const std::string& text,
  size_t at,
  const std::string& format,
  const std::vector<PLYElement>& elements,
  long long vertices)
{
  const bool ascii = format == "ascii";
  const bool big = format == "binary_big_endian";
  for (const auto& e : elements)
  {
    const bool face = e.Name == "face";
    for (long long i = 0; i < e.Number; ++i)
    {
      std::vector<std::string> w;
      size_t word = 0;
      if (ascii)
      {
        if (at >= text.size())
        {
          return "the file ends within element '" + e.Name + "'";
        }
        // VTK drops a last line without a line end and then frees the previous face's index
        // list a second time (abort or heap corruption even in a valid file).
        const size_t nl = text.find('\n', at);
        if (nl == std::string::npos)
        {
          return "the last line has no line end (VTK 9.1's PLY reader crashes on that; add one)";
        }
        const std::string line = text.substr(at, nl - at);
        at = nl + 1;
        if (line.size() > 4000)
        {
          return "line longer than 4000 characters";
        }
        w = PLYWords(line);
      }
      auto next = [&](int size, bool isSigned, bool isFloat, double& value)
      {
        if (!ascii)
        {
          return ReadPLYBinary(text, at, big, size, isSigned, isFloat, value);
        }
        if (word >= w.size())
        {
          return false;
        }
        value = std::strtod(w[word++].c_str(), nullptr);
        return true;
      };
      for (const auto& p : e.Properties)
      {
        double value = 0;
        if (p.Count == 0)
        {
          if (!next(p.Size, true, p.Float, value))
          {
            return "element '" + e.Name + "' " + std::to_string(i) + " is short of values";
          }
          continue;
        }
        double count = 0;
        if (!next(p.Count, p.CountSigned, false, count) || count < 0 || count > 0x7fffffff)
        {
          return "element '" + e.Name + "' " + std::to_string(i) + ": invalid list count";
        }
        const bool indices = face && p.Name == "vertex_indices";
        if (indices && count > 256)
        {
          return "face " + std::to_string(i) + " has more than 256 vertices";
        }
        for (long long k = 0; k < static_cast<long long>(count); ++k)
        {
          if (!next(p.Size, true, p.Float, value))
          {
            return "element '" + e.Name + "' " + std::to_string(i) + " is short of values";
          }
          if (indices && !(value >= 0 && value < static_cast<double>(vertices)))
          {
            return "face " + std::to_string(i) + " names a vertex that does not exist";
          }
        }
      }
    }
  }
  return std::string();
}

// VTK 9.1's PLY reader goes on with a closed file when the vertex element or its x, y, z is
// missing (use after free), reads one word per property from each ASCII line however many
// there are, copies a face's indices into an array of 256 and reads the points they name
// before anything checks them, and frees a face's index list even when the element has none
// (found by fuzzing). Checked here: the header, and every element of the body (ASCII or
// binary) against it; faces have at most 256 indices, each naming a vertex. Empty if fine.
std::string PLYProblem(const std::string& path)
{
  const std::string text = FileContents(path);
  std::vector<PLYElement> elements;
  std::string format;
  size_t at = 0;
  std::string problem = ParsePLYHeader(text, at, format, elements);
  const PLYElement* vertex = nullptr;
  if (problem.empty())
  {
    problem = PLYElementsProblem(elements, vertex);
  }
  return problem.empty() ? PLYBodyProblem(text, at, format, elements, vertex->Number) : problem;
}

// The checks of GLTFProblem, one method per part of the document. Problem holds the first
// problem found (some checks go on and keep the last, as they always did).
class GLTFChecker
{
public:
  GLTFChecker(const std::string& path, bool binary)
    : Path(path)
    , Binary(binary)
    , File(FileContents(path))
  {
  }

  std::string Run();

private:
  std::string ReadGLB(std::string& json);
  bool Parse(const std::string& json);
  bool ReadArrays();
  std::string ObjectsProblem();
  long long Integer(const Json::Value& object, const char* key, const std::string& where);
  long long Reference(const Json::Value& object,
    const char* key,
    const Json::Value& list,
    const std::string& where);
  void NodeList(const Json::Value& list, const std::string& otherwise);
  static std::string Name(const char* kind, Json::ArrayIndex i)
  {
    return std::string(kind) + "[" + std::to_string(i) + "]";
  }
  void CheckBuffers();
  std::string BufferBytes(long long i);
  void CheckBufferViews();
  void CheckAccessors();
  void CheckSparse(const Json::Value& a,
    const std::string& where,
    long long count,
    long long element);
  void CheckMeshes();
  void CheckPrimitive(const Json::Value& primitive, const std::string& where);
  void CheckNodes();
  void CheckNodeCycles();
  void CheckOtherReferences();

  std::string Path;
  bool Binary;
  std::string File;
  long long BinChunk = -1; // the GLB's BIN chunk size (-1: none)
  size_t BinStart = 0;
  Json::Value Root;
  std::string Problem;
  const Json::Value* Scenes = nullptr;
  const Json::Value* Nodes = nullptr;
  const Json::Value* Meshes = nullptr;
  const Json::Value* Accessors = nullptr;
  const Json::Value* Views = nullptr;
  const Json::Value* Buffers = nullptr;
  const Json::Value* Materials = nullptr;
  const Json::Value* Textures = nullptr;
  const Json::Value* Images = nullptr;
  const Json::Value* Samplers = nullptr;
  const Json::Value* Skins = nullptr;
  const Json::Value* Cameras = nullptr;
  const Json::Value* Animations = nullptr;
  std::vector<long long> BufferSizes;
  std::vector<std::string> BufferFiles; // external buffers: the file's path
  std::vector<long long> ViewSizes, ViewOffsets, ViewBuffers;
};

// The JSON chunk of a GLB (the BIN chunk's size and start are kept). Empty if fine.
std::string GLTFChecker::ReadGLB(std::string& json)
{
  auto u32 = [&](size_t at)
  {
    return static_cast<unsigned long long>(static_cast<unsigned char>(this->File[at])) |
      static_cast<unsigned long long>(static_cast<unsigned char>(this->File[at + 1])) << 8 |
      static_cast<unsigned long long>(static_cast<unsigned char>(this->File[at + 2])) << 16 |
      static_cast<unsigned long long>(static_cast<unsigned char>(this->File[at + 3])) << 24;
  };
  if (this->File.size() < 20 || this->File.compare(0, 4, "glTF") != 0 || u32(16) != 0x4E4F534Aull)
  {
    return "not a GLB file (no glTF header and JSON chunk)";
  }
  const unsigned long long jsonLength = u32(12);
  if (jsonLength > this->File.size() - 20)
  {
    return "GLB JSON chunk longer than the file";
  }
  json = this->File.substr(20, jsonLength);
  const unsigned long long next = 20 + jsonLength;
  if (next + 8 <= this->File.size())
  {
    const unsigned long long binLength = u32(next);
    if (binLength > this->File.size() - next - 8)
    {
      return "GLB binary chunk longer than the file";
    }
    this->BinChunk = static_cast<long long>(binLength);
    this->BinStart = next + 8;
  }
  return std::string();
}

bool GLTFChecker::Parse(const std::string& json)
{
  Json::CharReaderBuilder builder;
  std::string errors;
  std::istringstream in(json);
  return Json::parseFromStream(builder, in, &this->Root, &errors) && this->Root.isObject();
}

// The top-level arrays (a missing one is empty). False (with the problem) when one is not an
// array.
bool GLTFChecker::ReadArrays()
{
  auto array = [&](const char* name) -> const Json::Value*
  {
    static const Json::Value empty(Json::arrayValue);
    const Json::Value& v = this->Root[name];
    if (!v.isNull() && !v.isArray())
    {
      this->Problem = std::string("'") + name + "' is not an array";
    }
    return v.isArray() ? &v : &empty;
  };
  this->Scenes = array("scenes");
  this->Nodes = array("nodes");
  this->Meshes = array("meshes");
  this->Accessors = array("accessors");
  this->Views = array("bufferViews");
  this->Buffers = array("buffers");
  this->Materials = array("materials");
  this->Textures = array("textures");
  this->Images = array("images");
  this->Samplers = array("samplers");
  this->Skins = array("skins");
  this->Cameras = array("cameras");
  this->Animations = array("animations");
  return this->Problem.empty();
}

// Every item of every top-level array must be an object. Empty if fine.
std::string GLTFChecker::ObjectsProblem()
{
  for (const char* kind : { "scenes",
         "nodes",
         "meshes",
         "accessors",
         "bufferViews",
         "buffers",
         "materials",
         "textures",
         "images",
         "samplers",
         "skins",
         "cameras",
         "animations" })
  {
    for (const auto& item : this->Root[kind])
    {
      if (!item.isObject())
      {
        return std::string(kind) + " holds something that is not an object";
      }
    }
  }
  return std::string();
}

// An optional non-negative integer below 2^31 (VTK keeps them in int), -1 when absent.
long long GLTFChecker::Integer(const Json::Value& object, const char* key, const std::string& where)
{
  const Json::Value& v = object.isObject() ? object[key] : Json::Value::nullSingleton();
  if (v.isNull())
  {
    return -1LL;
  }
  if (!v.isIntegral() || v.asLargestInt() < 0 || v.asLargestInt() > 0x7fffffff)
  {
    this->Problem = where + "." + key + " is not a valid number";
    return -1LL;
  }
  return static_cast<long long>(v.asLargestInt());
}

// An optional reference @p key of @p object into @p list.
long long GLTFChecker::Reference(const Json::Value& object,
  const char* key,
  const Json::Value& list,
  const std::string& where)
{
  const long long i = this->Integer(object, key, where);
  if (this->Problem.empty() && i >= static_cast<long long>(list.size()))
  {
    this->Problem = where + "." + key + " = " + std::to_string(i) + " does not exist";
  }
  return i;
}

// A list of node indices (children, a scene's nodes, a skin's joints): each must exist.
void GLTFChecker::NodeList(const Json::Value& list, const std::string& otherwise)
{
  for (const auto& node : list)
  {
    if (!node.isIntegral() || node.asLargestInt() < 0 ||
      node.asLargestInt() >= static_cast<Json::LargestInt>(this->Nodes->size()))
    {
      this->Problem = otherwise;
    }
  }
}

void GLTFChecker::CheckBuffers()
{
  const Json::Value& buffers = *this->Buffers;
  // The actual size of each buffer: the GLB's BIN chunk, else byteLength (VTK requires an
  // external file to be that long and sizes a data: URI buffer to it).
  for (Json::ArrayIndex i = 0; i < buffers.size(); ++i)
  {
    this->BufferFiles.emplace_back();
    long long size = this->Integer(buffers[i], "byteLength", Name("buffers", i));
    const Json::Value& uri = buffers[i]["uri"];
    if (this->Problem.empty() && size < 0)
    {
      this->Problem = Name("buffers", i) + " has no byteLength"; // VTK skips it: indices shift
    }
    if (i == 0 && this->Binary)
    {
      // VTK uses the BIN chunk as the first buffer, which must then have no uri.
      if (!uri.isNull() || this->BinChunk < 0)
      {
        this->Problem = "the first buffer of a GLB must be its binary chunk";
      }
      size = this->BinChunk;
    }
    else if (!uri.isString())
    {
      this->Problem = Name("buffers", i) + " has no uri";
    }
    else if (uri.asString().compare(0, 5, "data:") != 0)
    {
      // VTK loads nothing (and reads on) unless the file beside has exactly byteLength bytes.
      const std::string file = uri.asString();
      const auto slash = this->Path.find_last_of('/');
      const std::string full = !file.empty() && file[0] == '/'
        ? file
        : (slash == std::string::npos ? std::string() : this->Path.substr(0, slash + 1)) + file;
      this->BufferFiles.back() = full;
      std::ifstream in(full, std::ios::binary | std::ios::ate);
      if (!in.good() || static_cast<long long>(in.tellg()) != size)
      {
        this->Problem = Name("buffers", i) + ": '" + file + "' is missing or not byteLength bytes";
      }
    }
    this->BufferSizes.push_back(std::max(0LL, size));
  }
}

// The bytes of a buffer (read only for sparse accessors, whose indices are checked).
std::string GLTFChecker::BufferBytes(long long i)
{
  const Json::Value& buffers = *this->Buffers;
  const Json::Value& uri = buffers[static_cast<Json::ArrayIndex>(i)]["uri"];
  if (i == 0 && this->Binary)
  {
    return this->File.substr(this->BinStart, static_cast<size_t>(this->BinChunk));
  }
  if (!this->BufferFiles[i].empty())
  {
    return FileContents(this->BufferFiles[i]);
  }
  const std::string data = uri.asString();
  const size_t comma = data.find(',');
  if (comma == std::string::npos)
  {
    return std::string();
  }
  std::string bytes(static_cast<size_t>(this->BufferSizes[i]), '\0');
  bytes.resize(vtksysBase64_Decode(reinterpret_cast<const unsigned char*>(data.data()) + comma + 1,
    bytes.size(),
    reinterpret_cast<unsigned char*>(&bytes[0]),
    data.size() - comma - 1));
  return bytes;
}

void GLTFChecker::CheckBufferViews()
{
  const Json::Value& views = *this->Views;
  const Json::Value& buffers = *this->Buffers;
  for (Json::ArrayIndex i = 0; i < views.size() && this->Problem.empty(); ++i)
  {
    const std::string where = Name("bufferViews", i);
    const long long buffer = this->Reference(views[i], "buffer", buffers, where);
    const long long offset = std::max(0LL, this->Integer(views[i], "byteOffset", where));
    const long long length = this->Integer(views[i], "byteLength", where);
    if (this->Problem.empty() && (buffer < 0 || length < 0))
    {
      this->Problem = where + " has no buffer or no byteLength"; // VTK skips it: indices shift
    }
    this->Integer(views[i], "byteStride", where);
    // The specification allows only these two; VTK 9.5 rejects others itself, VTK 9.1 reads
    // on and crashes in accessor extraction (Testing/Fuzz/known-vtk-crashes/gltf-*), and
    // 9.5's loader once crashed on such a file under load: rejected here, before any reader.
    const long long target = this->Integer(views[i], "target", where);
    if (this->Problem.empty() && target >= 0 && target != 34962 && target != 34963)
    {
      this->Problem = where + ".target is " + std::to_string(target) +
        ", neither ARRAY_BUFFER (34962) nor ELEMENT_ARRAY_BUFFER (34963)";
    }
    if (this->Problem.empty() && (buffer < 0 || offset + length > this->BufferSizes[buffer]))
    {
      this->Problem = where + " lies outside its buffer";
    }
    this->ViewSizes.push_back(length);
    this->ViewOffsets.push_back(offset);
    this->ViewBuffers.push_back(buffer);
  }
}

void GLTFChecker::CheckAccessors()
{
  const Json::Value& accessors = *this->Accessors;
  const Json::Value& views = *this->Views;
  for (Json::ArrayIndex i = 0; i < accessors.size() && this->Problem.empty(); ++i)
  {
    const Json::Value& a = accessors[i];
    const std::string where = Name("accessors", i);
    static const std::map<int, int> componentBytes = {
      { 5120, 1 }, { 5121, 1 }, { 5122, 2 }, { 5123, 2 }, { 5125, 4 }, { 5126, 4 }
    };
    static const std::map<std::string, int> typeComponents = { { "SCALAR", 1 },
      { "VEC2", 2 },
      { "VEC3", 3 },
      { "VEC4", 4 },
      { "MAT2", 4 },
      { "MAT3", 9 },
      { "MAT4", 16 } };
    const long long component = this->Integer(a, "componentType", where);
    const std::string type = a["type"].isString() ? a["type"].asString() : std::string();
    const long long count = this->Integer(a, "count", where);
    if (this->Problem.empty() &&
      (!componentBytes.count(static_cast<int>(component)) || !typeComponents.count(type) ||
        count < 0))
    {
      this->Problem = where + " has no valid componentType, type and count";
    }
    const long long view = this->Reference(a, "bufferView", views, where);
    const long long offset = std::max(0LL, this->Integer(a, "byteOffset", where));
    const long long element = this->Problem.empty()
      ? componentBytes.at(static_cast<int>(component)) * typeComponents.at(type)
      : 0;
    if (this->Problem.empty() && view >= 0 && count > 0)
    {
      const Json::Value& bufferView = views[static_cast<Json::ArrayIndex>(view)];
      const long long stride = std::max(element, this->Integer(bufferView, "byteStride", where));
      if (offset + (count - 1) * stride + element > this->ViewSizes[view])
      {
        this->Problem = where + " reads past the end of its buffer view";
      }
    }
    if (this->Problem.empty() && a.isMember("sparse"))
    {
      this->CheckSparse(a, where, count, element);
    }
  }
}

void GLTFChecker::CheckSparse(const Json::Value& a,
  const std::string& where,
  long long count,
  long long element)
{
  const Json::Value& views = *this->Views;
  // VTK writes each sparse value at the index the file gives, unchecked: the indices are
  // read here. VTK 9.1 also requires both byteOffsets, which glTF lets default to 0 (without
  // them it skips the accessor, and every later index shifts).
  const Json::Value& sparse = a["sparse"];
  const std::string at = where + ".sparse";
  const Json::Value& indices = sparse["indices"];
  const Json::Value& values = sparse["values"];
  const long long n = this->Integer(sparse, "count", at);
  const long long indexView = this->Reference(indices, "bufferView", views, at + ".indices");
  const long long valueView = this->Reference(values, "bufferView", views, at + ".values");
  const long long indexOffset = this->Integer(indices, "byteOffset", at + ".indices");
  const long long valueOffset = this->Integer(values, "byteOffset", at + ".values");
  const long long indexType = this->Integer(indices, "componentType", at + ".indices");
  const int indexBytes = indexType == 5121 ? 1 : indexType == 5123 ? 2 : indexType == 5125 ? 4 : 0;
  if (this->Problem.empty() &&
    (n < 1 || n > count || indexView < 0 || valueView < 0 || indexOffset < 0 || valueOffset < 0 ||
      indexBytes == 0))
  {
    this->Problem = at + " needs a count of at most the accessor's, buffer views, byteOffsets " +
      "and an unsigned index type";
  }
  if (this->Problem.empty() &&
    (indexOffset + n * indexBytes > this->ViewSizes[indexView] ||
      valueOffset + n * element > this->ViewSizes[valueView]))
  {
    this->Problem = at + " reads past the end of its buffer views";
  }
  if (this->Problem.empty())
  {
    const std::string bytes = this->BufferBytes(this->ViewBuffers[indexView]);
    const long long start = this->ViewOffsets[indexView] + indexOffset;
    if (start + n * indexBytes > static_cast<long long>(bytes.size()))
    {
      this->Problem = at + ".indices: the buffer is shorter than its byteLength";
    }
    for (long long k = 0; k < n && this->Problem.empty(); ++k)
    {
      unsigned long long index = 0;
      for (int b = indexBytes - 1; b >= 0; --b)
      {
        index = index << 8 | static_cast<unsigned char>(bytes[start + k * indexBytes + b]);
      }
      if (index >= static_cast<unsigned long long>(count))
      {
        this->Problem = at + ": index " + std::to_string(index) + " beyond the accessor's " +
          std::to_string(count) + " elements";
      }
    }
  }
}

void GLTFChecker::CheckMeshes()
{
  const Json::Value& meshes = *this->Meshes;
  for (Json::ArrayIndex i = 0; i < meshes.size() && this->Problem.empty(); ++i)
  {
    const Json::Value& primitives = meshes[i]["primitives"];
    if (!primitives.isArray())
    {
      this->Problem = Name("meshes", i) + ".primitives is not an array";
      break;
    }
    for (Json::ArrayIndex j = 0; j < primitives.size() && this->Problem.empty(); ++j)
    {
      this->CheckPrimitive(
        primitives[j], Name("meshes", i) + ".primitives[" + std::to_string(j) + "]");
    }
  }
}

void GLTFChecker::CheckPrimitive(const Json::Value& primitive, const std::string& where)
{
  const Json::Value& accessors = *this->Accessors;
  const Json::Value& materials = *this->Materials;
  if (!primitive.isObject() || !primitive["attributes"].isObject())
  {
    this->Problem = where + " has no attributes";
    return;
  }
  for (const auto& key : primitive["attributes"].getMemberNames())
  {
    this->Reference(primitive["attributes"], key.c_str(), accessors, where + ".attributes");
  }
  // VTK builds no points unless every attribute comes from a buffer view, and then
  // dereferences them.
  if (this->Problem.empty() && !primitive["attributes"].isMember("POSITION"))
  {
    this->Problem = where + " has no POSITION";
  }
  for (const auto& key : primitive["attributes"].getMemberNames())
  {
    const long long a = this->Problem.empty()
      ? this->Reference(primitive["attributes"], key.c_str(), accessors, where + ".attributes")
      : -1;
    if (this->Problem.empty() &&
      this->Integer(accessors[static_cast<Json::ArrayIndex>(a)], "bufferView", where) < 0)
    {
      this->Problem = where + ".attributes." + key + " has no buffer view";
    }
  }
  const long long indices = this->Reference(primitive, "indices", accessors, where);
  if (this->Problem.empty() && indices >= 0)
  {
    // VTK reads it from view -1 without one, and builds no points if it is not SCALAR of an
    // unsigned integer type (then dereferences them).
    const Json::Value& a = accessors[static_cast<Json::ArrayIndex>(indices)];
    const long long component = this->Integer(a, "componentType", where);
    if (this->Integer(a, "bufferView", where) < 0 || a["type"] != "SCALAR" ||
      (component != 5121 && component != 5123 && component != 5125))
    {
      this->Problem = where + ".indices is not an unsigned SCALAR accessor with a buffer view";
    }
  }
  this->Reference(primitive, "material", materials, where);
  const Json::Value& targets = primitive["targets"];
  for (Json::ArrayIndex t = 0; t < targets.size() && this->Problem.empty(); ++t)
  {
    if (!targets[t].isObject())
    {
      this->Problem = where + ".targets holds something that is not an object";
      break;
    }
    for (const auto& key : targets[t].getMemberNames())
    {
      this->Reference(targets[t], key.c_str(), accessors, where + ".targets");
    }
  }
}

void GLTFChecker::CheckNodes()
{
  const Json::Value& nodes = *this->Nodes;
  const Json::Value& meshes = *this->Meshes;
  const Json::Value& skins = *this->Skins;
  const Json::Value& cameras = *this->Cameras;
  for (Json::ArrayIndex i = 0; i < nodes.size() && this->Problem.empty(); ++i)
  {
    const Json::Value& node = nodes[i];
    const std::string where = Name("nodes", i);
    this->Reference(node, "mesh", meshes, where);
    this->Reference(node, "skin", skins, where);
    this->Reference(node, "camera", cameras, where);
    this->NodeList(node["children"], where + " has a child that does not exist");
    const std::pair<const char*, Json::ArrayIndex> sizes[] = {
      { "matrix", 16 }, { "translation", 3 }, { "rotation", 4 }, { "scale", 3 }
    };
    for (const auto& size : sizes)
    {
      const Json::Value& v = node[size.first];
      if (!v.isNull() && (!v.isArray() || v.size() != size.second))
      {
        this->Problem =
          where + "." + size.first + " does not have " + std::to_string(size.second) + " numbers";
      }
      for (const auto& number : v)
      {
        if (!number.isNumeric())
        {
          this->Problem = where + "." + size.first + " holds something that is not a number";
        }
      }
    }
  }
}

// The node hierarchy must be a forest: VTK walks it recursively.
void GLTFChecker::CheckNodeCycles()
{
  const Json::Value& nodes = *this->Nodes;
  std::vector<int> state(nodes.size(), 0); // 0 unvisited, 1 on the path, 2 done
  std::function<bool(Json::ArrayIndex)> acyclic = [&](Json::ArrayIndex n)
  {
    if (state[n] == 1)
    {
      return false;
    }
    if (state[n] == 2)
    {
      return true;
    }
    state[n] = 1;
    for (const auto& child : nodes[n]["children"])
    {
      if (!acyclic(static_cast<Json::ArrayIndex>(child.asLargestInt())))
      {
        return false;
      }
    }
    state[n] = 2;
    return true;
  };
  for (Json::ArrayIndex i = 0; i < nodes.size() && this->Problem.empty(); ++i)
  {
    if (!acyclic(i))
    {
      this->Problem = "the node hierarchy has a cycle";
    }
  }
}

// The default scene, the scenes' nodes, skins, textures, images, materials and animations.
void GLTFChecker::CheckOtherReferences()
{
  const Json::Value& scenes = *this->Scenes;
  const Json::Value& nodes = *this->Nodes;
  const Json::Value& accessors = *this->Accessors;
  const Json::Value& views = *this->Views;
  const Json::Value& materials = *this->Materials;
  const Json::Value& textures = *this->Textures;
  const Json::Value& images = *this->Images;
  const Json::Value& samplers = *this->Samplers;
  const Json::Value& skins = *this->Skins;
  const Json::Value& animations = *this->Animations;
  const long long scene =
    this->Problem.empty() ? this->Reference(this->Root, "scene", scenes, "document") : -1;
  if (this->Problem.empty() && scene < 0 && this->Root.isMember("scene") == false && scenes.empty())
  {
    this->Problem = "no scene";
  }
  for (Json::ArrayIndex i = 0; i < scenes.size() && this->Problem.empty(); ++i)
  {
    this->NodeList(scenes[i]["nodes"], Name("scenes", i) + " has a node that does not exist");
  }
  for (Json::ArrayIndex i = 0; i < skins.size() && this->Problem.empty(); ++i)
  {
    this->Reference(skins[i], "inverseBindMatrices", accessors, Name("skins", i));
    this->Reference(skins[i], "skeleton", nodes, Name("skins", i));
    this->NodeList(skins[i]["joints"], Name("skins", i) + " has a joint that does not exist");
  }
  for (Json::ArrayIndex i = 0; i < textures.size() && this->Problem.empty(); ++i)
  {
    this->Reference(textures[i], "source", images, Name("textures", i));
    this->Reference(textures[i], "sampler", samplers, Name("textures", i));
  }
  for (Json::ArrayIndex i = 0; i < images.size() && this->Problem.empty(); ++i)
  {
    this->Reference(images[i], "bufferView", views, Name("images", i));
  }
  for (Json::ArrayIndex i = 0; i < materials.size() && this->Problem.empty(); ++i)
  {
    const Json::Value& m = materials[i];
    for (const Json::Value* info : { &m["pbrMetallicRoughness"]["baseColorTexture"],
           &m["pbrMetallicRoughness"]["metallicRoughnessTexture"],
           &m["normalTexture"],
           &m["occlusionTexture"],
           &m["emissiveTexture"] })
    {
      this->Reference(*info, "index", textures, Name("materials", i));
    }
  }
  for (Json::ArrayIndex i = 0; i < animations.size() && this->Problem.empty(); ++i)
  {
    const Json::Value& animationSamplers = animations[i]["samplers"];
    for (const auto& sampler : animationSamplers)
    {
      this->Reference(sampler, "input", accessors, Name("animations", i) + ".samplers");
      this->Reference(sampler, "output", accessors, Name("animations", i) + ".samplers");
    }
    for (const auto& channel : animations[i]["channels"])
    {
      this->Reference(channel, "sampler", animationSamplers, Name("animations", i) + ".channels");
      this->Reference(channel["target"], "node", nodes, Name("animations", i) + ".channels.target");
    }
  }
}

std::string GLTFChecker::Run()
{
  std::string json = this->File;
  if (this->Binary)
  {
    const std::string problem = this->ReadGLB(json);
    if (!problem.empty())
    {
      return problem;
    }
  }
  if (!this->Parse(json))
  {
    return "invalid JSON";
  }
  if (!this->ReadArrays())
  {
    return this->Problem;
  }
  const std::string problem = this->ObjectsProblem();
  if (!problem.empty())
  {
    return problem;
  }
  this->CheckBuffers();
  this->CheckBufferViews();
  this->CheckAccessors();
  this->CheckMeshes();
  this->CheckNodes();
  if (this->Problem.empty())
  {
    this->CheckNodeCycles();
  }
  this->CheckOtherReferences();
  return this->Problem;
}

// VTK 9.1's glTF loader and importer index scenes, nodes, meshes, accessors, buffer views and
// buffers with the numbers of the document, and read accessors from buffer views and buffers,
// without checking either (heap overflows, use after free, null dereferences, node cycles that
// recurse forever; found by fuzzing); a GLB chunk length is allocated as declared. Checked here
// on the JSON before VTK sees the file. Empty if fine.
std::string GLTFProblem(const std::string& path, bool binary)
{
  return GLTFChecker(path, binary).Run();
}

//------------------------------------------------------------------------------
std::string ReaderCrashProblem(const std::function<void()>& read)
{
#ifdef VTKAO_HAS_FORK
#ifdef VTKAO_ASAN
  // The sanitizers' allocators are not fork-safe (GCC 12's and clang 14's runtimes): a child
  // forked while another thread holds one of their locks waits forever in malloc (seen under
  // libFuzzer, whose threads allocate). Under them, only a single-threaded process checks.
  if (ThreadCount() != 1)
  {
    return std::string();
  }
#endif
  std::fflush(nullptr); // nothing buffered is written twice
  const pid_t child = fork();
  if (child < 0)
  {
    return std::string();
  }
  if (child == 0)
  {
    // Quiet, and a crash only ends the child: the parent reports it. Crash signals get their
    // default action back (no handler of a fuzzer or debugger writes a report), and a
    // sanitizer's report goes nowhere and ends in an exit status (the parent's own read of a
    // file that passes is still checked by it).
    for (int s : { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT })
    {
      signal(s, SIG_DFL);
    }
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0)
    {
      dup2(null, 1);
      dup2(null, 2);
#ifdef VTKAO_ASAN
      __sanitizer_set_report_fd(reinterpret_cast<void*>(static_cast<intptr_t>(null)));
      __sanitizer_set_death_callback([] { _exit(1); });
#endif
    }
    // Only this thread exists in the child: VTK's SMP backend (TBB) would wait for workers
    // that were not forked.
    vtkSMPTools::SetBackend("Sequential");
    try
    {
      read();
    }
    catch (...)
    {
      // The parent's read throws the same, and reports it.
    }
    _exit(0); // no atexit handlers, no flushing of the parent's buffers
  }
  // A reader that never finishes is not a crash: after a minute the child is stopped and the
  // parent reads as it would have without it (a safeguard: no hang is known).
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  auto pause = std::chrono::microseconds(200);
  int status = 0;
  for (;;)
  {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child)
    {
      break;
    }
    if ((done < 0 && errno != EINTR) || Clock::now() > deadline)
    {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      return std::string();
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  if (WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) != 0))
  {
    return "the VTK reader crashed on it (malformed file)";
  }
#else
  (void)read;
#endif
  return std::string();
}
}
