// Small pieces the vtkao program's subcommands share (the ray-traced and the baking ones).
#ifndef vtkaoProgram_h
#define vtkaoProgram_h

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"

#include <unistd.h> // isatty

#include <algorithm>
#include <cstdio> // fileno
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace vtkao
{
/// @p s as a JSON string literal: quotes and backslashes escaped, control characters (which a
/// JSON string may not hold raw) written as spaces.
inline std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      out += ' ';
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

// A text progress bar on stderr. On a terminal it is redrawn in place ("\r") when the
// percentage changes; redirected to a file or a pipe (CI logs) it writes two lines, one when the
// work starts and one when it ends, instead of a hundred carriage-return updates.
class ProgressBar
{
public:
  explicit ProgressBar(const std::string& label)
    : Label(label)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject* caller, unsigned long, void* client, void* data)
      {
        auto* self = static_cast<ProgressBar*>(client);
        double fraction = data ? *static_cast<double*>(data) : 0.0;
        if (auto* algorithm = vtkAlgorithm::SafeDownCast(caller))
        {
          fraction = algorithm->GetProgress();
        }
        self->Show(fraction);
      });
  }
  ~ProgressBar() { this->Finish(); }

  void Watch(vtkObject* object) { object->AddObserver(vtkCommand::ProgressEvent, this->Command); }

  void Show(double fraction)
  {
    const int percent = static_cast<int>(100.0 * std::min(1.0, std::max(0.0, fraction)));
    if (percent == this->Shown)
    {
      return;
    }
    const bool first = this->Shown < 0;
    this->Shown = percent;
    if (!this->Terminal)
    {
      if (first)
      {
        std::cerr << this->Label << " ..." << std::endl;
      }
      return;
    }
    const int width = 40, filled = percent * width / 100;
    std::cerr << "\r" << this->Label << " [" << std::string(filled, '#')
              << std::string(width - filled, ' ') << "] " << percent << "%" << std::flush;
  }

  void Finish()
  {
    if (this->Shown >= 0)
    {
      if (this->Terminal)
      {
        std::cerr << "\n";
      }
      else
      {
        std::cerr << this->Label << " done (" << this->Shown << "%)" << std::endl;
      }
      this->Shown = -1;
    }
  }

private:
  std::string Label;
  int Shown = -1;
  bool Terminal = isatty(fileno(stderr)) != 0;
  vtkNew<vtkCallbackCommand> Command;
};

// The visible opaque actors whose mapper draws a vtkPolyData, and that polydata.
inline std::vector<std::pair<vtkActor*, vtkPolyData*>> PolyDataActors(vtkRenderer* renderer)
{
  std::vector<std::pair<vtkActor*, vtkPolyData*>> actors;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    auto* actor = vtkActor::SafeDownCast(prop);
    auto* mapper = actor ? vtkPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper || !actor->GetVisibility())
    {
      continue;
    }
    actor->GetBounds(); // updates the mapper's input
    auto* data = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
    if (data && actor->HasOpaqueGeometry())
    {
      actors.emplace_back(actor, data);
    }
  }
  return actors;
}
}

#endif
