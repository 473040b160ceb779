/**
 * @class   vtkAOOpenGLBaker
 * @brief   base of the bakers that draw with OpenGL: the context they draw in
 *
 * vtkAOSattlerBaker and vtkAOHemisphereBaker draw into framebuffer objects of their own in the
 * context of RenderWindow; if none is set the baker creates an off-screen vtkRenderWindow of its
 * own (released with the baker). Any vtkOpenGLRenderWindow with OpenGL 3.2 works; the window's
 * framebuffer, size and OpenGL state are left as they were. The rest (ports, surface, normals,
 * output array) is vtkAOBaker's.
 */
#ifndef vtkAOOpenGLBaker_h
#define vtkAOOpenGLBaker_h

#include "vtkAOBaker.h"
#include "vtkSmartPointer.h"   // for vtkSmartPointer
#include "vtkaoBakingModule.h" // For export macro

#include <memory> // for std::unique_ptr

class vtkOpenGLRenderWindow;
class vtkRenderWindow;

class VTKAOBAKING_EXPORT vtkAOOpenGLBaker : public vtkAOBaker
{
public:
  vtkTypeMacro(vtkAOOpenGLBaker, vtkAOBaker);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OpenGL context to draw in (a vtkOpenGLRenderWindow). nullptr (the default): an
   * off-screen window of the baker's own. The window's framebuffer and size are not touched.
   */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkRenderWindow* GetRenderWindow() { return this->RenderWindow; }
  ///@}

  /**
   * Release the OpenGL resources (and the internal window). Called by the destructor.
   */
  void ReleaseGraphicsResources();

  ///@{
  /**
   * Statistics of the last execution: the occluding triangles drawn, and the seconds spent
   * drawing them and reading the results back (what each baker counts in: see its own
   * statistics).
   */
  vtkGetMacro(NumberOfTriangles, vtkIdType);
  vtkGetMacro(RenderTime, double);
  ///@}

protected:
  vtkAOOpenGLBaker();
  ~vtkAOOpenGLBaker() override;

  /**
   * What a subclass makes in the context (framebuffers, textures, buffers): Release() is called
   * by ReleaseGraphicsResources, when the window changes and by the destructor, while the
   * window is still alive.
   */
  class vtkContextResources
  {
  public:
    virtual ~vtkContextResources() = default;
    virtual void Release() = 0;
  };

  /**
   * The context to draw in, made current: RenderWindow, else the baker's own off-screen window
   * (created on first use). nullptr (after vtkErrorMacro) when it is not a
   * vtkOpenGLRenderWindow.
   */
  vtkOpenGLRenderWindow* MakeContext();

  /// Resets NumberOfTriangles and RenderTime.
  void InitializeResults(vtkIdType numberOfPoints) override;

  // Results.
  vtkIdType NumberOfTriangles = 0;
  double RenderTime = 0.0;

  vtkRenderWindow* RenderWindow = nullptr;
  vtkSmartPointer<vtkRenderWindow> OwnWindow;
  /// Set by the subclass's constructor; destroyed before OwnWindow.
  std::unique_ptr<vtkContextResources> ContextResources;

private:
  vtkAOOpenGLBaker(const vtkAOOpenGLBaker&) = delete;
  void operator=(const vtkAOOpenGLBaker&) = delete;
};

#endif
