// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkAOPixelList
 * @brief   The marked pixels of a frame as one compact list, traced densely and scattered back.
 *
 * Hybrid AO refines the few pixels its reduced map cannot represent (1-30 % of a frame, on
 * edges and fins). Shading only those pixels of a full-screen pass (the marks as a depth
 * attachment, rejected before shading) still runs the tracer in whole SIMD groups: a group
 * (a 2 x 2 quad on a GPU, a 4 x 4 block on llvmpipe) with one marked pixel costs as much as
 * a group of marked pixels, and the marked pixels are thin lines, not areas. This class packs
 * them instead (stream compaction with OpenGL 3.2's geometry shaders and transform feedback,
 * no compute shaders): Build() draws one point per 4 x 4 block of pixels; a geometry shader
 * emits one vertex per marked pixel, captured in order into a buffer. The refinement then
 * shades a dense rectangle of Width() x Rows() fragments, fragment i standing for entry i
 * (Bind() gives the shader the list), into GetDense(); Scatter() writes each entry's result
 * to its pixel (one point per entry, no tracing).
 *
 * Build() reads the number of entries back (a query the CPU waits for: the dense pass must
 * know its size). Not a wrapped class: an internal stage of vtkAOVoxelTracer.
 */
#ifndef vtkAOPixelList_h
#define vtkAOPixelList_h

#include "vtkObject.h"
#include "vtkaoRenderingModule.h" // For export macro

class vtkOpenGLBufferObject;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;
class vtkTextureObject;
class vtkTransformFeedback;
class vtkWindow;

class VTKAORENDERING_EXPORT vtkAOPixelList : public vtkObject
{
public:
  static vtkAOPixelList* New();
  vtkTypeMacro(vtkAOPixelList, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * List the pixels whose value in @p marks (a depth texture) is below 0.5, in the order of
   * their 4 x 4 blocks (rows of blocks, then rows within a block). False if the context cannot
   * (the caller then shades the marked pixels in place); the list is then empty.
   */
  bool Build(vtkOpenGLRenderWindow* renWin, vtkTextureObject* marks);

  /// Entries of the last Build().
  int GetCount() const { return this->Count; }

  /// The dense layout: entry i is fragment (i % GetWidth(), i / GetWidth()) of GetDense().
  int GetWidth() const { return this->Width; }
  int GetRows() const
  {
    return this->Count > 0 ? (this->Count + this->Width - 1) / this->Width : 0;
  }

  /**
   * Set a program's uniforms aoList (samplerBuffer: xy = the entry's pixel), aoListCount,
   * aoListWidth and aoListRows (GetRows()), activating the list's texture (Unbind()
   * deactivates it).
   */
  void Bind(vtkShaderProgram* program);
  void Unbind();

  /**
   * Shade the dense rectangle with @p quad (its program ready, its uniforms set, Bind() done)
   * into GetDense(), whose RG channels the caller's shader writes.
   */
  void DrawDense(vtkOpenGLRenderWindow* renWin, vtkOpenGLQuadHelper* quad);

  /// The dense results (RG32F, Width() x capacity rows).
  vtkTextureObject* GetDense() { return this->Dense; }

  /**
   * Write the RG channels of each entry's dense result to its pixel of @p target (a texture of
   * the marks' size); the other pixels and channels are left as they are.
   */
  bool Scatter(vtkOpenGLRenderWindow* renWin, vtkTextureObject* target);

  ///@{
  /**
   * The most entries a list holds, 0 (default) for as many as the GL's texture limits allow:
   * past it the marked pixels left out keep the reduced map (one warning). For tests, and to
   * bound the list's memory (24 bytes an entry).
   */
  vtkSetClampMacro(MaximumEntries, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumEntries, int);
  ///@}

  /// Free the buffers, textures and programs.
  void ReleaseGraphicsResources(vtkWindow* w);

  /// Bytes of GPU memory in the list's buffer and the dense texture.
  long long GetGraphicsMemorySize();

protected:
  vtkAOPixelList();
  ~vtkAOPixelList() override;

  /// Make room for @p entries entries (grows the buffer, its texture and the dense texture).
  bool Reserve(vtkOpenGLRenderWindow* renWin, int entries);

  int Count = 0;
  int Capacity = 0;
  int Width = 1024;
  int MaximumEntries = 0;
  vtkOpenGLBufferObject* Buffer = nullptr;
  vtkTextureObject* ListTexture = nullptr; ///< a buffer texture over Buffer (RGBA32F)
  vtkTextureObject* Dense = nullptr;
  vtkTransformFeedback* Capture = nullptr; ///< names the varying captured at link time
  vtkShaderProgram* CompactProgram = nullptr;
  vtkShaderProgram* ScatterProgram = nullptr;
  vtkOpenGLVertexArrayObject* Layout = nullptr; ///< no attributes: the shaders use gl_VertexID
  vtkOpenGLFramebufferObject* FrameBufferObject = nullptr;
  unsigned int Query = 0;        ///< GL_PRIMITIVES_GENERATED of the compaction
  bool Failed = false;           ///< the context could not build the programs: do not try again
  bool WarnedTruncation = false; ///< the list's limit was reached (warned once)

private:
  vtkAOPixelList(const vtkAOPixelList&) = delete;
  void operator=(const vtkAOPixelList&) = delete;
};

#endif
// VTK-HeaderTest-Exclude: vtkAOPixelList.h
