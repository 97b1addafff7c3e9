/**
 * @class   vtkAVSOcclusionPass
 * @brief   the ambient-occlusion volume computed on the GPU (private)
 *
 * The compute pass of avs_occlusion_cs.glsl: from sigma_t on the data grid (a temporary texture
 * that vtkAVSAveragedExtinctionPass::Classify fills from the uploaded scalars), the occlusion on
 * the target grid (the same box) is written into the ray caster's
 * Occlusion texture (vtkAVSVolumeTextures), with the sampling of the CPU code
 * (Rendering/Core/AmbientOcclusion.cxx): the same directions, steps and offsets.
 */
#ifndef vtkAVSOcclusionPass_h
#define vtkAVSOcclusionPass_h

#include "Grid.h"

#include <array>
#include <string>

class vtkAVSVolumeTextures;
class vtkTextureObject;

class vtkAVSOcclusionPass
{
public:
  vtkAVSOcclusionPass() = default;
  vtkAVSOcclusionPass(const vtkAVSOcclusionPass&) = delete;
  vtkAVSOcclusionPass& operator=(const vtkAVSOcclusionPass&) = delete;

  /// Builds the program (the context current); false when it does not compile.
  bool Build();
  /// Runs the pass (the caller checked for compute shaders and at most 256 directions).
  /// `sigma`: sigma_t at the voxels of the data grid `geometry`.
  bool Run(vtkAVSVolumeTextures& textures,
    const avs::GridGeometry& geometry,
    vtkTextureObject* sigma,
    const std::array<int, 3>& dimensions,
    double radius,
    int directions,
    std::string& error);
  /// Forgets the program, deleting it when its context is current (`context`).
  void ReleaseGraphicsResources(bool context);

private:
  unsigned int Program = 0; ///< GL name of the ambient-occlusion compute program
};

#endif
