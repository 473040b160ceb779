// Text placed in 3-D over occluded ground, with both passes: a vtkBillboardTextActor3D and a
// vtkTextActor3D lying on the ground beside the sphere, and a vtkFlagpoleLabel (a vtkActor
// without a mapper, as the cube and polar axes actors are) in front of it, each with an opaque
// background. ParaView's text source draws its billboard, 3-D text and flagpole modes with
// these classes. They are annotation (vtkAOPropGeometry::IsOverlay): drawn after the
// composite, depth-tested, neither darkened nor casting. Checks: their pixels are those of the
// same render without the pass; the ground under the labels is occluded and the ground in front
// of the sphere darkened; the AO image is the same with and without them; HAO voxelizes the
// ground and the sphere only. Before, the billboard and the 3-D text were drawn into the
// G-buffer and darkened by the ground's occlusion (yellow 255 -> 144 beside the sphere), and
// the flagpole label, an actor without a mapper counted as an occluder, crashed HAO's
// voxelization bookkeeping (a null mapper).
#include "vtkAOTestUtilities.h"
#include "vtkAmbientOcclusionVolumesPass.h"
#include "vtkBillboardTextActor3D.h"
#include "vtkFlagpoleLabel.h"
#include "vtkTextActor3D.h"
#include "vtkTextProperty.h"

#include <cstdlib>
#include <type_traits>

namespace
{
constexpr int Width = 400;
constexpr int Height = 300;

void Style(vtkTextProperty* text)
{
  text->SetFontSize(24);
  text->SetColor(0, 0, 1);
  text->SetBackgroundColor(1, 1, 0);
  text->SetBackgroundOpacity(1.0);
}

// The window's RGB pixels, row by row (Width x Height).
vtkSmartPointer<vtkUnsignedCharArray> GrabWindow(vtkRenderWindow* win)
{
  int w = 0;
  return vtkAOTest::GrabRGB(win, w);
}

template<typename Pass>
void Run(const char* what)
{
  using namespace vtkAOTest;
  const std::string name(what);
  vtkNew<vtkRenderer> ren;
  auto win = MakeObliqueSphereOnGround(ren, Width, Height);

  vtkNew<vtkBillboardTextActor3D> billboard;
  billboard->SetInput("AO");
  billboard->SetPosition(1.0, 0.02, 0.8);
  Style(billboard->GetTextProperty());
  vtkNew<vtkTextActor3D> text3D;
  text3D->SetInput("AO");
  text3D->SetPosition(-2.0, 0.01, 0.4);
  text3D->SetOrientation(-90, 0, 0); // flat on the ground, read from the camera
  text3D->SetScale(0.025);
  Style(text3D->GetTextProperty());
  vtkNew<vtkFlagpoleLabel> flagpole;
  flagpole->SetInput("AO");
  flagpole->SetBasePosition(2.4, 0, 2.2);
  flagpole->SetTopPosition(2.4, 0.3, 2.2);
  flagpole->SetFlagSize(1.5);
  Style(flagpole->GetTextProperty());
  vtkProp* labels[] = { billboard, text3D, flagpole };
  const char* labelNames[] = { "vtkBillboardTextActor3D", "vtkTextActor3D", "vtkFlagpoleLabel" };
  for (vtkProp* label : labels)
  {
    ren->AddViewProp(label);
  }
  auto show = [&labels](int k) // -1: all, -2: none
  {
    for (int i = 0; i < 3; ++i)
    {
      labels[i]->SetVisibility(k == -1 || k == i);
    }
  };

  // Without the pass: the image without labels, with each label, and with all of them. A
  // label's pixels are those its render changes.
  show(-2);
  win->Render();
  const auto bare = GrabWindow(win);
  std::vector<std::vector<int>> masks(3);
  for (int k = 0; k < 3; ++k)
  {
    show(k);
    win->Render();
    const auto one = GrabWindow(win);
    for (int i = 0; i < Width * Height; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        if (one->GetTypedComponent(i, c) != bare->GetTypedComponent(i, c))
        {
          masks[k].push_back(i);
          break;
        }
      }
    }
  }
  show(-1);
  win->Render();
  const auto plain = GrabWindow(win);

  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<Pass> pass;
  pass->SetDelegatePass(basic);
  pass->SetRadius(2.0);
  pass->SetIntensity(4.0);
  pass->SetAccumulation(false); // every render the same A, to compare without and with labels
  ren->SetPass(pass);
  show(-2);
  win->Render();
  const AOImage without = PassAOImage(pass.Get());
  show(-1);
  win->Render();
  Check(pass->GetLastFrameHadOcclusion(), name + ": the pass applied occlusion");
  const AOImage with = PassAOImage(pass.Get());
  const auto occluded = GrabWindow(win);
  const double difference = MaxAbsDifference(without, with);
  std::printf("%s: largest change of A from the labels %.4f\n", what, difference);
  Check(difference < 0.01, name + ": the labels leave the AO image as it is without them");
  if (std::is_same<Pass, vtkHybridAmbientOcclusionPass>::value)
  {
    auto* hao = vtkHybridAmbientOcclusionPass::SafeDownCast(pass.Get());
    std::printf("%s: voxelized props %d\n", what, hao->GetNumberOfVoxelizedProps());
    Check(hao->GetNumberOfVoxelizedProps() == 2, name + ": only the ground and the sphere occlude");
  }
  const auto front = GroundBox(ren, -0.2, 1.1, 0.2, 1.4);
  const auto open = GroundBox(ren, 3.2, 2.8, 3.6, 3.2);
  const double frontLuminance = MeanLuminance(win, front.data());
  const double openLuminance = MeanLuminance(win, open.data());
  Check(frontLuminance < 0.85 * openLuminance,
    name + ": the ground in front of the sphere is darkened in the image");
  const double openAO = MeanAO(pass, open.data());

  for (int k = 0; k < 3; ++k)
  {
    // A of the ground the label covers (as without the label), and how many of its pixels
    // differ from the render without the pass by more than 8 of 255.
    double meanA = 0;
    int covered = 0, off = 0, largest = 0;
    for (int i : masks[k])
    {
      if (without.Coverage[i] > 0.5f)
      {
        meanA += without.A[i];
        ++covered;
      }
      int change = 0;
      for (int c = 0; c < 3; ++c)
      {
        change = std::max(
          change, std::abs(occluded->GetTypedComponent(i, c) - plain->GetTypedComponent(i, c)));
      }
      largest = std::max(largest, change);
      off += change > 8 ? 1 : 0;
    }
    meanA /= std::max(covered, 1);
    const int n = static_cast<int>(masks[k].size());
    std::printf("%s: %s: %d pixels, A of the ground under them %.3f (open %.3f), %d off by more "
                "than 8/255 from the render without the pass (largest %d)\n",
      what,
      labelNames[k],
      n,
      meanA,
      openAO,
      off,
      largest);
    Check(n > 100, name + ": the " + labelNames[k] + " is seen");
    if (k < 2)
    {
      Check(covered > n / 2 && meanA < openAO - 0.03,
        name + ": the ground under the " + labelNames[k] + " is occluded");
    }
    Check(off <= n / 200,
      name + ": the " + labelNames[k] + " is drawn as without the pass (not darkened)");
  }
  ren->ReleaseGraphicsResources(win);
}
}

int TestAOTextLabels(int, char*[])
{
  Run<vtkHybridAmbientOcclusionPass>("HAO");
  Run<vtkAmbientOcclusionVolumesPass>("AOV");
  return vtkAOTest::Result();
}
