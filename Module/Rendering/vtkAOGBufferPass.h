/**
 * @class   vtkAOGBufferPass
 * @brief   Renders a delegate pass into the G-buffer the ambient-occlusion stages read.
 *
 * The delegate (usually a vtkRenderStepsPass) draws into an offscreen framebuffer with three
 * attachments: the shaded colour (RGBA8), the view-space shading normal (RGBA16F, w = 1
 * where an opaque polygonal prop wrote one), the view-space normal of the polygon's own plane
 * (RGBA16F, from the screen-space derivatives of the fragment's view position; w = 1 where
 * exact, 0 where the mapper's shader has no view position) and the depth (32-bit float).
 * Positions are not stored: the AO stages rebuild them exactly from the depth and the inverse
 * projection. The polygon's plane lets the tracer count rays that leave below the polygon
 * (interpolated normals lean away from it) as occluded by the polygon itself.
 *
 * Translucent props still draw their colour but write alpha 0 into the normal attachment,
 * which the blending of the translucent pass turns into "keep the opaque normal".
 *
 * Where an opaque prop wrote no normal (a shader without one, such as an unlit prop's, a
 * mapper outside vtkPolyDataMapper's render-pass hooks, or a visible prop that did not draw
 * through them with its property keys), Render completes the attachment afterwards with the
 * polygon's normal rebuilt from the neighbouring depths (w = 1), in one full-screen pass that
 * runs only for such frames (GetNormalsCompleted). The AO stages then read every normal with
 * one fetch.
 *
 * Used by vtkHybridAmbientOcclusionPass; reusable by any pass that needs p and n per pixel.
 */
#ifndef vtkAOGBufferPass_h
#define vtkAOGBufferPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkaoRenderingModule.h" // For export macro

#include <memory>        // For std::unique_ptr
#include <unordered_set> // For the props seen drawing

class vtkInformation;
class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

class VTKAORENDERING_EXPORT vtkAOGBufferPass : public vtkOpenGLRenderPass
{
public:
  static vtkAOGBufferPass* New();
  vtkTypeMacro(vtkAOGBufferPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The pass that draws the scene into the G-buffer. Default is none (nothing is drawn).
   */
  virtual void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  /**
   * Render the delegate into the G-buffer, sized to the renderer's tiled viewport (or to the
   * state's framebuffer when one is set).
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Free the textures, the framebuffer and the delegate's resources.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /// Bytes of GPU memory in the textures this stage owns (0 after ReleaseGraphicsResources).
  long long GetGraphicsMemorySize();

  ///@{
  /**
   * The G-buffer after Render(): colour, normal (view space) and depth textures, and their size.
   */
  vtkTextureObject* GetColorTexture() { return this->ColorTexture; }
  vtkTextureObject* GetNormalTexture() { return this->NormalTexture; }
  vtkTextureObject* GetFacetTexture() { return this->FacetTexture; }
  vtkTextureObject* GetDepthTexture() { return this->DepthTexture; }
  int GetWidth() const { return this->Size[0]; }
  int GetHeight() const { return this->Size[1]; }
  ///@}

  /**
   * Whether the last Render() completed the normal attachment from the depths: true where a
   * prop may have drawn without a normal (see the class description); false where every
   * visible prop drew through a shader that writes one.
   */
  bool GetNormalsCompleted() const { return this->NormalsCompleted; }

  ///@{
  /**
   * Give @p program what vtkAOCommon.glsl's aoViewPosition and aoViewNormal read: the depth
   * and normal textures (activated; aoDepth, aoNormal), the inverse of @p projection
   * (aoInvProjection), the G-buffer's size (aoFullSize) and whether the projection is
   * @p parallel (aoParallel). UnbindViewGeometry deactivates the textures.
   */
  void BindViewGeometry(vtkShaderProgram* program, vtkMatrix4x4* projection, bool parallel);
  void UnbindViewGeometry();
  ///@}

  /**
   * Plant the normal output after the mapper's lighting code.
   */
  bool PreReplaceShaderValues(std::string& vertexShader,
    std::string& geometryShader,
    std::string& fragmentShader,
    vtkAbstractMapper* mapper,
    vtkProp* prop) override;

  /**
   * Fill in the normal output (or a neutral one where the shader has no normal).
   */
  bool PostReplaceShaderValues(std::string& vertexShader,
    std::string& geometryShader,
    std::string& fragmentShader,
    vtkAbstractMapper* mapper,
    vtkProp* prop) override;

  /**
   * Enable the normal attachment for opaque polygonal props and tell the shader whether the
   * prop is opaque.
   */
  bool SetShaderParameters(vtkShaderProgram* program,
    vtkAbstractMapper* mapper,
    vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;

protected:
  vtkAOGBufferPass();
  ~vtkAOGBufferPass() override;

  /// Create or resize the attachments for a @p w x @p h viewport.
  void InitializeGraphicsResources(vtkOpenGLRenderWindow* renWin, int w, int h);

  /// Rebuild the normals the props did not write from the depths (vtkAONormalResolveFS);
  /// false if the pass could not run.
  bool CompleteNormals(vtkRenderer* ren, vtkOpenGLRenderWindow* renWin);

  /// BindViewGeometry without the normal and facet textures (for passes that write them).
  void BindDepthGeometry(vtkShaderProgram* program, vtkMatrix4x4* projection, bool parallel);

  vtkRenderPass* DelegatePass = nullptr;
  vtkOpenGLFramebufferObject* FrameBufferObject = nullptr;
  vtkTextureObject* ColorTexture = nullptr;
  vtkTextureObject* NormalTexture = nullptr;
  vtkTextureObject* FacetTexture = nullptr;
  vtkTextureObject* DepthTexture = nullptr;
  int Size[2] = { 0, 0 };
  bool Parallel = false; // the frame's camera, for the facets' orientation
  // This render: the property keys of the props seen drawing (a prop that draws through an
  // internal actor, such as vtkLODActor's device, hands it its keys). NormalsCompleted is set
  // while the delegate draws where a draw left normals missing, and after it where the
  // completion ran.
  std::unordered_set<vtkInformation*> DrawnKeys;
  bool NormalsCompleted = false;
  std::unique_ptr<vtkOpenGLQuadHelper> ResolveQuad;
  vtkOpenGLFramebufferObject* ResolveFramebuffer = nullptr;

private:
  vtkAOGBufferPass(const vtkAOGBufferPass&) = delete;
  void operator=(const vtkAOGBufferPass&) = delete;
};

#endif
