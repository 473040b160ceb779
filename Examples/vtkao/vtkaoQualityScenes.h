// The scenes of `vtkao quality` (issue 3): each one isolates a situation where AO methods
// differ (contact, creases, occluders outside the view or hidden, thin plates, glyphs, an
// iso-surface, real meshes from Debian packages), with a fixed camera and radius.
#ifndef vtkaoQualityScenes_h
#define vtkaoQualityScenes_h

#include <functional>
#include <string>
#include <vector>

class vtkRenderer;

namespace vtkao
{
struct QualityScene
{
  std::string Name;
  std::string Description;
  /// Occluders a screen-space method cannot see (off screen, hidden): the HAO/SSAO ratio goal
  /// is a quarter there instead of a half.
  bool ScreenSpaceBlind = false;
  /// Add the actors and set the camera for an image of aspect @p aspect (width / height).
  /// Sets @p radius (world units). Returns false and sets @p note when the scene cannot be
  /// built (a real-mesh file is missing).
  std::function<bool(vtkRenderer*, double aspect, double& radius, std::string& note)> Build;
};

/// All scenes, in table order.
std::vector<QualityScene> QualityScenes();
}

#endif
