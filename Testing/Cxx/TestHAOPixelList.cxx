// vtkAOPixelList, the compaction behind HAO's listed refinement, on its own: Build() lists
// exactly the marked pixels of a marks texture whose size is no multiple of its 4 x 4 blocks,
// growing past its first capacity (a 16th of the frame) when more are marked; a dense pass
// reads each entry's pixel and Scatter() writes it back to that pixel and nowhere else; with
// MaximumEntries below the count it lists that many, warns once, and scatters no others; a GL
// error left pending by another stage does not turn it off.
#include "vtkAOGL.h" // glGetTexImage
#include "vtkAOPixelList.h"
#include "vtkAOTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <vector>

namespace
{
// Each dense fragment writes its entry's pixel + 1 (so that 0 means "never written").
const char* EntryPixelFS = R"(//VTK::System::Dec
in vec2 texCoord;
uniform samplerBuffer aoList;
uniform int aoListCount;
uniform int aoListWidth;
uniform int aoListRows;
//VTK::Output::Dec
void main()
{
  ivec2 dims = ivec2(aoListWidth, aoListRows);
  ivec2 f = min(ivec2(texCoord * vec2(dims)), dims - 1);
  int i = f.y * aoListWidth + f.x;
  gl_FragData[0] = i < aoListCount ? vec4(texelFetch(aoList, i).xy + vec2(1.0), 0.0, 0.0)
                                   : vec4(0.0);
}
)";

struct Listing
{
  int Count = 0;
  int Right = 0; // marked pixels holding their own coordinates + 1
  int Wrong = 0; // pixels holding anything else (unmarked ones written, wrong coordinates)
};

Listing ListAndScatter(vtkOpenGLRenderWindow* renWin,
  vtkAOPixelList* list,
  vtkTextureObject* marks,
  const std::vector<float>& marked,
  int w,
  int h)
{
  Listing r;
  if (!list->Build(renWin, marks))
  {
    return r;
  }
  r.Count = list->GetCount();
  vtkOpenGLQuadHelper quad(renWin, nullptr, EntryPixelFS, "");
  if (!quad.Program || !quad.Program->GetCompiled())
  {
    return r;
  }
  renWin->GetShaderCache()->ReadyShaderProgram(quad.Program);
  list->Bind(quad.Program);
  list->DrawDense(renWin, &quad);
  list->Unbind();

  vtkNew<vtkTextureObject> target;
  target->SetContext(renWin);
  std::vector<float> zeros(static_cast<size_t>(2) * w * h, 0.0f);
  target->Create2DFromRaw(w, h, 2, VTK_FLOAT, zeros.data());
  if (!list->Scatter(renWin, target))
  {
    return r;
  }
  std::vector<float> out(zeros.size());
  target->Activate();
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, out.data());
  target->Deactivate();
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const size_t i = static_cast<size_t>(y) * w + x;
      const float u = out[2 * i], v = out[2 * i + 1];
      if (u == 0.0f && v == 0.0f)
      {
        continue; // not written
      }
      if (marked[i] < 0.5f && u == x + 1.0f && v == y + 1.0f)
      {
        ++r.Right;
      }
      else
      {
        ++r.Wrong;
      }
    }
  }
  target->ReleaseGraphicsResources(renWin);
  return r;
}
}

int TestHAOPixelList(int, char*[])
{
  using namespace vtkAOTest;
  vtkNew<vtkRenderer> ren;
  auto win = MakeWindow(64, 64, ren);
  win->Render();
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(win);
  Check(renWin != nullptr, "an OpenGL render window");
  if (!renWin)
  {
    return Result();
  }
  renWin->MakeCurrent();

  // 30 % of a 509 x 403 frame marked (61,542 pixels: more than the first capacity of 16,384
  // and than a 16th of the frame, 12,820), in a pattern that crosses the 4 x 4 blocks.
  const int w = 509, h = 403;
  std::vector<float> marked(static_cast<size_t>(w) * h, 1.0f);
  int expected = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      if ((7 * x + 13 * y) % 10 < 3)
      {
        marked[static_cast<size_t>(y) * w + x] = 0.0f;
        ++expected;
      }
    }
  }
  vtkNew<vtkTextureObject> marks;
  marks->SetContext(renWin);
  marks->Create2DFromRaw(w, h, 1, VTK_FLOAT, marked.data());

  vtkNew<vtkAOPixelList> list;
  const Listing all = ListAndScatter(renWin, list, marks, marked, w, h);
  std::printf("%d marked: listed %d, scattered to their own pixels %d, elsewhere %d; %d rows\n",
    expected,
    all.Count,
    all.Right,
    all.Wrong,
    list->GetRows());
  Check(all.Count == expected, "every marked pixel is listed, once");
  Check(all.Right == expected && all.Wrong == 0,
    "each entry's result reaches its own pixel, and no other pixel is written");
  Check(list->GetRows() == (expected + list->GetWidth() - 1) / list->GetWidth(),
    "the dense rectangle has the rows the count needs");

  // A cap below the count: that many entries, one warning, the others left as they were.
  int warnings = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&warnings);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  list->AddObserver(vtkCommand::WarningEvent, counter);
  list->SetMaximumEntries(5000);
  const Listing capped = ListAndScatter(renWin, list, marks, marked, w, h);
  const Listing again = ListAndScatter(renWin, list, marks, marked, w, h);
  std::printf("capped at 5000: listed %d, right %d, wrong %d; warnings %d\n",
    capped.Count,
    capped.Right,
    capped.Wrong,
    warnings);
  Check(capped.Count == 5000 && capped.Right == 5000 && capped.Wrong == 0 && again.Count == 5000,
    "MaximumEntries caps the list; the entries it holds are still right");
  Check(warnings == 1, "the cap is warned about once");

  // An error another stage left pending (GL_INVALID_ENUM here) is not the list's allocation
  // failing: a fresh list still lists (it used to turn itself off for good).
  vtkNew<vtkAOPixelList> fresh;
  glEnable(0xFFFF);
  Check(fresh->Build(renWin, marks) && fresh->GetCount() == expected,
    "a GL error pending from elsewhere does not turn the list off");
  fresh->ReleaseGraphicsResources(renWin);

  list->ReleaseGraphicsResources(renWin);
  marks->ReleaseGraphicsResources(renWin);
  return Result();
}
