#include "vtkaoCompare.h"

#include "vtkaoImageFile.h"
#include "vtkaoImageIO.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkStdString.h"
#include "vtkTextProperty.h"
#include "vtkTextRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>

namespace vtkao
{
namespace
{
// A top-down RGB float image (the grid under construction).
struct Canvas
{
  int Width = 0, Height = 0;
  std::vector<float> RGB;
  float* At(int x, int y) { return &this->RGB[3 * (static_cast<size_t>(y) * this->Width + x)]; }
};

// Read a panel the program wrote (PNG; 1-4 channels) into @p canvas at (x0, y0), top-down,
// alpha composited over white (the A-only images have an alpha channel).
void PastePanel(const std::string& path, Canvas& canvas, int x0, int y0, int width, int height)
{
  int w = 0, h = 0, channels = 0;
  std::vector<float> pixels;
  char error[512] = "";
  const bool ok = ReadImageFile(path.c_str(), &w, &h, &channels, &pixels, error, sizeof(error));
  if (!ok || w != width || h != height || channels < 1 || channels > 4)
  {
    throw std::runtime_error("cannot read the panel '" + path + "'");
  }
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const float* p = &pixels[(static_cast<size_t>(y) * width + x) * channels];
      float rgb[3];
      float alpha = 1.0f;
      if (channels >= 3)
      {
        std::copy_n(p, 3, rgb);
        alpha = channels == 4 ? p[3] : 1.0f;
      }
      else
      {
        rgb[0] = rgb[1] = rgb[2] = p[0];
        alpha = channels == 2 ? p[1] : 1.0f;
      }
      float* out = canvas.At(x0 + x, y0 + y);
      for (int c = 0; c < 3; ++c)
      {
        out[c] = alpha * rgb[c] + (1.0f - alpha);
      }
    }
  }
}

// Draw @p text with FreeType (vtkTextRenderer: no OpenGL needed) at the top-left corner
// (x0, y0) of a panel, black on a translucent white box.
void DrawLabel(const std::string& text,
  Canvas& canvas,
  int x0,
  int y0,
  int panelWidth,
  int panelHeight,
  int fontSize)
{
  vtkTextRenderer* renderer = vtkTextRenderer::GetInstance();
  if (!renderer)
  {
    throw std::runtime_error("no text renderer (VTK::RenderingFreeType is not initialized)");
  }
  vtkNew<vtkTextProperty> property;
  property->SetFontFamilyToArial();
  property->SetFontSize(fontSize);
  property->SetColor(0, 0, 0);
  property->SetBackgroundColor(1, 1, 1);
  property->SetBackgroundOpacity(0.8);
  property->BoldOn();
  vtkNew<vtkImageData> image;
  int dims[2] = { 0, 0 };
  if (!renderer->RenderString(property, vtkStdString(text), image, dims, 72))
  {
    throw std::runtime_error("cannot render the label '" + text + "'");
  }
  int extent[6];
  image->GetExtent(extent);
  const int w = extent[1] - extent[0] + 1, h = extent[3] - extent[2] + 1;
  const int nc = image->GetNumberOfScalarComponents();
  const int margin = std::max(2, fontSize / 3);
  for (int y = 0; y < std::min(h, dims[1]); ++y)
  {
    // vtkImageData rows are bottom-up; the canvas is top-down.
    const int cy = y0 + margin + (dims[1] - 1 - y);
    if (cy < y0 || cy >= y0 + panelHeight)
    {
      continue;
    }
    for (int x = 0; x < std::min(w, dims[0]); ++x)
    {
      const int cx = x0 + margin + x;
      if (cx >= x0 + panelWidth)
      {
        break;
      }
      const auto* p =
        static_cast<unsigned char*>(image->GetScalarPointer(extent[0] + x, extent[2] + y, 0));
      const float alpha = nc == 4 ? p[3] / 255.0f : 1.0f;
      float* out = canvas.At(cx, cy);
      for (int c = 0; c < 3; ++c)
      {
        out[c] = alpha * (p[std::min(c, nc - 1)] / 255.0f) + (1.0f - alpha) * out[c];
      }
    }
  }
}

std::string Label(const std::string& method)
{
  static const std::map<std::string, std::string> labels = { { "none", "none (no AO)" },
    { "ssao", "SSAO (vtkSSAOPass)" },
    { "hao", "HAO (hybrid AO)" },
    { "aov", "AOV (AO volumes)" },
    { "reference", "reference (ray traced A)" } };
  const auto it = labels.find(method);
  return it == labels.end() ? method : it->second;
}

// Removes the files it holds when it goes out of scope (on success and on failure).
struct TemporaryFiles
{
  std::vector<std::string> Paths;
  ~TemporaryFiles()
  {
    for (const auto& p : this->Paths)
    {
      std::remove(p.c_str());
    }
  }
};
}

//------------------------------------------------------------------------------
bool HasCompare(int argc, char* argv[])
{
  for (int i = 0; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--compare")
    {
      return true;
    }
  }
  return false;
}

namespace
{
// The steps of RenderComparison.

// The arguments of `render --compare`: the list and the output taken out, the others (with
// --size, which the layout needs) passed on to every panel's render.
struct CompareArguments
{
  std::vector<std::string> Rest;
  std::string List, Output;
  bool HasList = false;
  int Width = 1280, Height = 720;
};

CompareArguments SplitArguments(int argc, char* argv[])
{
  CompareArguments a;
  for (int i = 0; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--compare" || arg == "--output" || arg == "--method" || arg == "--timings")
    {
      if (arg == "--method" || arg == "--timings")
      {
        throw CompareUsageError("--compare: " + arg + " cannot be combined with --compare");
      }
      if (i + 1 >= argc)
      {
        throw CompareUsageError(arg + ": missing value");
      }
      (arg == "--compare" ? a.List : a.Output) = argv[++i];
      a.HasList = a.HasList || arg == "--compare";
      continue;
    }
    if (arg == "--size" && i + 1 < argc)
    {
      // Validated by the render itself; needed here for the layout.
      std::sscanf(argv[i + 1], "%dx%d", &a.Width, &a.Height);
    }
    a.Rest.push_back(arg);
  }
  return a;
}

// The methods of the list: known, available, not repeated, at least one; and a .png output.
std::vector<std::string> CheckedMethods(const CompareArguments& a,
  const std::vector<std::string>& available)
{
  std::vector<std::string> methods;
  std::stringstream in(a.List);
  std::string item;
  while (std::getline(in, item, ','))
  {
    if (std::find(available.begin(), available.end(), item) == available.end())
    {
      std::string expected;
      for (const auto& name : available)
      {
        expected += (expected.empty() ? "" : ",") + name;
      }
      throw CompareUsageError(
        "--compare: unknown method '" + item + "' (expected a list of " + expected + ")");
    }
    if (std::find(methods.begin(), methods.end(), item) != methods.end())
    {
      throw CompareUsageError("--compare: method '" + item + "' is listed twice");
    }
    methods.push_back(item);
  }
  if (!a.HasList || methods.empty())
  {
    throw CompareUsageError("--compare: expected a comma-separated list of methods");
  }
  if (a.Output.empty())
  {
    throw CompareUsageError("--output FILE.png is required");
  }
  std::string ext = a.Output.size() >= 4 ? a.Output.substr(a.Output.size() - 4) : "";
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".png")
  {
    throw CompareUsageError(
      "--output: unsupported format for '" + a.Output + "' with --compare (expected .png)");
  }
  return methods;
}

// One render per method, into a PNG beside the output (its path added to @p panels). Returns
// the first non-zero exit code of a render, else 0.
int RenderPanels(const CompareArguments& a,
  const std::vector<std::string>& methods,
  const RenderFunction& render,
  TemporaryFiles& panels)
{
  for (const auto& method : methods)
  {
    const std::string panel = a.Output + ".compare-" + method + ".png";
    panels.Paths.push_back(panel);
    std::vector<std::string> args = a.Rest;
    args.insert(args.end(), { "--method", method, "--output", panel });
    std::vector<char*> argvPanel;
    for (auto& arg : args)
    {
      argvPanel.push_back(&arg[0]);
    }
    argvPanel.push_back(nullptr);
    const int rc = render(static_cast<int>(args.size()), argvPanel.data());
    if (rc != 0)
    {
      return rc;
    }
  }
  return 0;
}

// The grid of the labelled panels: one row up to three panels, else two rows; 4 px white gaps.
// Rows bottom-up, as WriteImage takes them.
FloatImage ComposeGrid(const CompareArguments& a,
  const std::vector<std::string>& methods,
  const TemporaryFiles& panels)
{
  const int width = a.Width, height = a.Height;
  const int n = static_cast<int>(methods.size());
  const int columns = n <= 3 ? n : (n + 1) / 2;
  const int rows = (n + columns - 1) / columns;
  const int gap = 4;
  Canvas canvas;
  canvas.Width = columns * width + (columns - 1) * gap;
  canvas.Height = rows * height + (rows - 1) * gap;
  canvas.RGB.assign(3 * static_cast<size_t>(canvas.Width) * canvas.Height, 1.0f);
  const int fontSize = std::max(10, std::min(48, height / 18));
  for (int i = 0; i < n; ++i)
  {
    const int x0 = (i % columns) * (width + gap), y0 = (i / columns) * (height + gap);
    PastePanel(panels.Paths[i], canvas, x0, y0, width, height);
    DrawLabel(Label(methods[i]), canvas, x0, y0, width, height, fontSize);
  }

  FloatImage image;
  image.Width = canvas.Width;
  image.Height = canvas.Height;
  image.Channels = 3;
  image.Pixels.resize(canvas.RGB.size());
  const size_t stride = 3 * static_cast<size_t>(canvas.Width);
  for (int y = 0; y < canvas.Height; ++y) // top-down -> bottom-up
  {
    std::copy_n(&canvas.RGB[y * stride], stride, &image.Pixels[(canvas.Height - 1 - y) * stride]);
  }
  return image;
}
}

//------------------------------------------------------------------------------
int RenderComparison(int argc,
  char* argv[],
  const std::vector<std::string>& available,
  const RenderFunction& render)
{
  const CompareArguments a = SplitArguments(argc, argv);
  const std::vector<std::string> methods = CheckedMethods(a, available);
  TemporaryFiles panels;
  const int rc = RenderPanels(a, methods, render, panels);
  if (rc != 0)
  {
    return rc;
  }
  WriteImage(ComposeGrid(a, methods, panels), a.Output);
  std::cout << "wrote " << a.Output << " (" << methods.size() << " panels: " << a.List << ", "
            << a.Width << "x" << a.Height << " each)\n";
  return 0;
}
}
