/**
 * @class   vtkAVSDiffuseVolume
 * @brief   the extended model's diffuse fluence on the GPU (private)
 *
 * Holds the RGB fluence phi of the extended model (Core/DiffuseFluence.h) as a 3D texture on
 * the diffusion grid, uploaded from the core's CPU solve, and binds it for the ray-casting
 * program (avs_as_effect.glsl, AVS_DIFFUSE: u_diffuse, u_diffuseDimensions). Kept apart from
 * vtkAVSRayCaster, which only owns one and calls Bind / Unbind / ReleaseGraphicsResources.
 */
#ifndef vtkAVSDiffuseVolume_h
#define vtkAVSDiffuseVolume_h

#include "Grid.h"

#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class vtkAVSDiffuseVolume
{
public:
  vtkAVSDiffuseVolume();
  ~vtkAVSDiffuseVolume();
  vtkAVSDiffuseVolume(const vtkAVSDiffuseVolume&) = delete;
  vtkAVSDiffuseVolume& operator=(const vtkAVSDiffuseVolume&) = delete;

  /// Uploads phi (three grids on one geometry: R, G, B) into the texture of `window`'s context.
  bool Upload(vtkOpenGLRenderWindow* window, const std::vector<avs::Grid>& phi, std::string& error);
  /// Whether a fluence is uploaded.
  bool IsReady() const { return this->Texture != nullptr; }
  /// Activates the texture and sets the program's u_diffuse and u_diffuseDimensions.
  void Bind(vtkShaderProgram* program);
  void Unbind();
  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> Texture;
  std::array<int, 3> Dimensions{ 0, 0, 0 };
};

#endif
