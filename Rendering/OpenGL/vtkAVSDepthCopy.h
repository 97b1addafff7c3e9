/**
 * @class   vtkAVSDepthCopy
 * @brief   the depth of what was drawn before the volume, as a texture (private)
 *
 * Blits the depth of the read framebuffer's rectangle (the renderer's or a render pass's) into
 * a depth texture of the same format (queried: depth blits need identical formats), with the
 * scissor test off, which would clip the blit. A blit resolves multisampled framebuffers, and
 * Mesa refuses glCopyTexImage2D from some single-sampled ones (vtkToneMappingPass's float depth
 * renderbuffer). Without a readable depth the copy is cleared to 1 (no geometry), with one
 * warning. The ray caster's rays end at this depth.
 */
#ifndef vtkAVSDepthCopy_h
#define vtkAVSDepthCopy_h

#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for vtkSmartPointer<vtkTextureObject>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkWindow;

class vtkAVSDepthCopy
{
public:
  vtkAVSDepthCopy();
  ~vtkAVSDepthCopy();
  vtkAVSDepthCopy(const vtkAVSDepthCopy&) = delete;
  vtkAVSDepthCopy& operator=(const vtkAVSDepthCopy&) = delete;

  /// Copies the depth of the read framebuffer's rectangle at (x, y) of `window`'s context into
  /// the texture (made again when the size or the format changes).
  void Capture(vtkOpenGLRenderWindow* window, int x, int y, int width, int height);
  /// The copy (null before the first Capture).
  vtkTextureObject* GetTexture() const { return this->Depth; }
  /// Releases the texture and the framebuffer (in the current context, `window`'s): kept, the
  /// framebuffer would bind a deleted window's context in the next one.
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  int Format = 0;
  bool WarningGiven = false;
};

#endif
