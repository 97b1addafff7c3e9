/**
 * @class   vtkAVSImageSampler
 * @brief   draws the ray-casting pass at an image sample distance other than 1 (private)
 *
 * The mappers' ImageSampleDistance d (VTK's meaning: d pixels per ray along each axis; 2 casts
 * one ray for every 2 x 2 pixels, 0.5 four rays per pixel): the pass is rendered into an
 * offscreen target of ceil(width / d) x ceil(height / d) texels (half floats, premultiplied
 * colour and opacity), each texel one ray through its place in the viewport, then composited,
 * interpolated bilinearly, over the viewport of the framebuffer that was bound, with the blending
 * the caller set for the full-resolution pass (ONE, ONE_MINUS_SRC_ALPHA). The pass reads the
 * opaque depth from a texture over the viewport, so geometry ends its rays as at full
 * resolution.
 */
#ifndef vtkAVSImageSampler_h
#define vtkAVSImageSampler_h

#include "DisplayTransform.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <memory>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkAVSImageSampler
{
public:
  vtkAVSImageSampler();
  ~vtkAVSImageSampler();
  vtkAVSImageSampler(const vtkAVSImageSampler&) = delete;
  vtkAVSImageSampler& operator=(const vtkAVSImageSampler&) = delete;

  /// Draws `pass` (binds its program and draws it over the current viewport, blending and depth
  /// state as the caller set them) at image sample distance `distance` over the viewport (x, y,
  /// width, height) of the bound draw framebuffer. Returns false having drawn nothing when
  /// `distance` is 1 (unless `always`: a volume split into bricks composites its passes in the
  /// target's half floats instead of the framebuffer's 8 bits), or when the target cannot be
  /// made (with a warning, once); the caller then draws at full resolution. The target's linear
  /// radiance goes through `display` as it is composited.
  bool Draw(vtkOpenGLRenderWindow* window,
    int x,
    int y,
    int width,
    int height,
    double distance,
    const std::function<void()>& pass,
    const avs::DisplayTransform& display,
    bool always = false);

  /// Texels of the last target drawn into (rays cast).
  int GetTargetWidth() const { return this->Width; }
  int GetTargetHeight() const { return this->Height; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  bool EnsureTarget(vtkOpenGLRenderWindow* window, int width, int height);

  vtkOpenGLRenderWindow* Window = nullptr;
  vtkSmartPointer<vtkTextureObject> Target;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Composite;
  int Width = 0, Height = 0;
  bool WarningGiven = false;
};

#endif
