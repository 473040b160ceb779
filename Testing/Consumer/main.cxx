// Constructs the pass from the vtkao package and checks its defaults.
#include "vtkHybridAmbientOcclusionPass.h"
#include "vtkNew.h"
#include "vtkRenderStepsPass.h"

#include <cstdio>
#include <string>

int main()
{
  vtkNew<vtkRenderStepsPass> basic;
  vtkNew<vtkHybridAmbientOcclusionPass> hao;
  hao->SetDelegatePass(basic);
  hao->SetRadius(2.0);
  const bool ok = hao->GetRadius() == 2.0 && hao->GetNumberOfRays() == 8 &&
    hao->GetDelegatePass() == basic.Get() &&
    std::string(hao->GetClassName()) == "vtkHybridAmbientOcclusionPass";
  std::printf("%s: constructed %s\n", ok ? "ok" : "FAILED", hao->GetClassName());
  return ok ? 0 : 1;
}
