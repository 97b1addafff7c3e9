/**
 * @class   vtkAVSOcclusionPass
 * @brief   the ambient-occlusion volume computed on the GPU (private)
 *
 * The compute pass of avs_occlusion_cs.glsl: the extinction grid goes up as a temporary texture,
 * and the occlusion on the target grid (the same box) is written into the ray caster's
 * Occlusion texture (vtkAVSVolumeTextures), with the sampling of the CPU code
 * (Rendering/Core/AmbientOcclusion.cxx): the same directions, steps and offsets.
 */
#ifndef vtkAVSOcclusionPass_h
#define vtkAVSOcclusionPass_h

#include "Grid.h"

#include <array>
#include <string>

class vtkAVSVolumeTextures;

class vtkAVSOcclusionPass
{
public:
  vtkAVSOcclusionPass() = default;
  vtkAVSOcclusionPass(const vtkAVSOcclusionPass&) = delete;
  vtkAVSOcclusionPass& operator=(const vtkAVSOcclusionPass&) = delete;

  /// Builds the program (the context current); false when it does not compile.
  bool Build();
  /// Runs the pass (the caller checked for compute shaders and at most 256 directions).
  bool Run(vtkAVSVolumeTextures& textures,
    const avs::Grid& extinction,
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
