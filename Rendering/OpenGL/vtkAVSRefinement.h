/**
 * @class   vtkAVSRefinement
 * @brief   the path-traced refinement's buffers and passes (private)
 *
 * vtkAmbientScatteringVolumeMapper::PathTracedRefinement: while nothing changes from one frame to
 * the next (the key the mapper computes, and the viewport's size), each full-resolution frame
 * adds one path-traced sample per pixel (avs_pathtrace_fs.glsl) to two float buffers, the sums of
 * the samples and of their squares, and shows the ambient-scattering picture of the first still
 * frame moved towards their running mean (avs_refine_fs.glsl, Rendering/Core/Refinement.h). A new
 * key or size restarts: no samples, and the next still frame takes the ambient-scattering picture
 * again. Fragment passes only (no compute shader), so it runs wherever the ray caster runs.
 */
#ifndef vtkAVSRefinement_h
#define vtkAVSRefinement_h

#include "DisplayTransform.h"
#include "Refinement.h"
#include "vtkSmartPointer.h"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkAVSRefinement
{
public:
  vtkAVSRefinement();
  ~vtkAVSRefinement();
  vtkAVSRefinement(const vtkAVSRefinement&) = delete;
  vtkAVSRefinement& operator=(const vtkAVSRefinement&) = delete;

  /// A frame of the refinement: restarts when `key` (compared exactly), `geometry` (compared to
  /// a millionth) or the size differs from the last frame's. False, with the reason, when the
  /// float buffers cannot be made.
  bool Begin(vtkOpenGLRenderWindow* window,
    int width,
    int height,
    const std::vector<double>& key,
    const std::vector<double>& geometry,
    std::string& error);
  /// Whether the ambient-scattering picture of this key is held.
  bool HasAmbient() const { return this->AmbientHeld; }
  /// Draws `pass` (the ray caster's, radiance left linear) into the ambient buffer, over
  /// transparent black with the caller's blending.
  void CaptureAmbient(const std::function<void()>& pass);
  /// Uploads the cells' majorants (`cells` per axis, x fastest) when `version` is not the
  /// uploaded one.
  bool UpdateMajorants(const std::vector<float>& values,
    const std::array<int, 3>& cells,
    int version,
    std::string& error);
  /// Adds one sample per pixel: the path tracer built for `defines`, its uniforms set by
  /// `setUniforms` (the majorants' are set here), drawn into the sums.
  bool AddSample(const std::string& defines,
    const std::function<void(vtkShaderProgram*)>& setUniforms,
    std::string& error);
  /// Composites the refined picture, through `display`, over the viewport (x, y, width, height)
  /// of the bound framebuffer with the caller's blending.
  bool Show(int x, int y, int width, int height, const avs::DisplayTransform& display);

  /// Forgets the samples and the ambient picture and frees the buffers (a frame that is not
  /// refined); the next refined frame restarts.
  void Reset();
  /// Samples per pixel taken since the last restart.
  int GetSamples() const { return this->Samples; }
  /// Reads the buffers back (the window's context current): the ambient picture, the mean and
  /// the mean of the squares. False when there is no sample.
  bool Download(avs::RefinementBuffers& buffers);

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  bool EnsureBuffers(int width, int height, std::string& error);
  void Clear();

  vtkOpenGLRenderWindow* Window = nullptr;
  vtkSmartPointer<vtkTextureObject> Sum, SumSquares, Ambient, Majorants;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Accumulation, AmbientTarget;
  std::unique_ptr<vtkOpenGLQuadHelper> PathTracer, Picture;
  std::string PathTracerDefines;
  std::vector<double> Key, Geometry;
  std::array<int, 3> MajorantCells{ 0, 0, 0 };
  int MajorantsVersion = -1;
  int Width = 0, Height = 0;
  int Samples = 0;
  bool AmbientHeld = false;
};

#endif
