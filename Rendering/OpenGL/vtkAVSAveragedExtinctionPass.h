/**
 * @class   vtkAVSAveragedExtinctionPass
 * @brief   the averaged extinction computed on the GPU (private)
 *
 * The compute pass of avs_average_cs.glsl over the ray caster's textures
 * (vtkAVSVolumeTextures): passes 1-3 box-sum sigma_t (pass 1 classifies the uploaded scalars
 * as it reads them, zero outside the clip region) along x, y and z with the averaging half
 * widths, each axis interpolated onto the light grid as it is summed, into AveragedExtinction,
 * which the light-volume pass and the ray caster sample. Passes 1 and 2 go slab by slab along
 * z, so that pass 1's result (light-grid x by data y by data z floats otherwise, a byte per
 * voxel at 512^3 with a 128^3 light grid) is held for at most SlabBytes at a time. The CPU
 * twin is Rendering/Core/AveragedExtinction.cxx.
 */
#ifndef vtkAVSAveragedExtinctionPass_h
#define vtkAVSAveragedExtinctionPass_h

#include "ClipRegion.h"
#include "vtkAVSClassification.h"

#include <array>
#include <string>

class vtkAVSVolumeTextures;
class vtkTextureObject;

class vtkAVSAveragedExtinctionPass
{
public:
  /// The most that pass 1's result takes at once (bytes of the slab's floats; at least one
  /// slice): 16 MiB, or AVS_AVERAGING_SLAB_BYTES from the environment where set (so that a test
  /// on a small volume can make the passes go in several slabs).
  static double SlabBytes();

  vtkAVSAveragedExtinctionPass() = default;
  vtkAVSAveragedExtinctionPass(const vtkAVSAveragedExtinctionPass&) = delete;
  vtkAVSAveragedExtinctionPass& operator=(const vtkAVSAveragedExtinctionPass&) = delete;

  /// The widest ring of classified values pass 1 keeps (entries): 256, windows of up to 127
  /// voxels either side, or AVS_AVERAGING_WINDOW_RING from the environment where set (so that a
  /// test can make pass 1 classify each voxel twice, with 0).
  static int MaximumWindowRing();
  /// The ring pass 1 keeps for a window of half width `halfWidth` voxels: the smallest power of
  /// two above 2 halfWidth + 1, or 0 where that is above MaximumWindowRing (then each voxel is
  /// classified again when it leaves the window).
  static int WindowRing(int halfWidth);

  /// The programs for a classification layout and pass 1's half width along x (built again when
  /// its defines change or the window needs a wider ring): pass 1's, which classifies, and that
  /// of passes 2 and 3, which sum the pass before's grid; pass 1's program, 0 when either does
  /// not compile.
  unsigned int Build(const vtkAVSClassification::Layout& layout, int halfWidth = 0);
  /// Runs the passes (the caller checked for compute shaders, scalars and classification).
  bool Run(vtkAVSVolumeTextures& textures,
    const std::array<int, 3>& dimensions,
    const std::array<int, 3>& lightDimensions,
    const std::array<int, 3>& halfWidths,
    const avs::ClipRegion& clip,
    std::string& error);
  /// sigma_t at each voxel of the data's grid `dimensions` into `target` (an R32F texture of
  /// that size), classified from the uploaded scalars as pass 1 classifies them (0 outside
  /// `clip`): the ambient-occlusion pass's input, so that no extinction grid is made on the CPU.
  bool Classify(vtkAVSVolumeTextures& textures,
    const std::array<int, 3>& dimensions,
    const avs::ClipRegion& clip,
    vtkTextureObject* target,
    std::string& error);
  /// Forgets the program, deleting it when its context is current (`context`).
  void ReleaseGraphicsResources(bool context);

private:
  /// The program made current with the classification and clipping bound.
  bool Begin(vtkAVSVolumeTextures& textures,
    const avs::ClipRegion& clip,
    int halfWidth,
    double inverseCount,
    std::string& error);
  /// One pass over the grid `in` (pass 1: the data, or its slab from `zOffset`).
  void Dispatch(int pass,
    vtkTextureObject* input,
    vtkTextureObject* output,
    const std::array<int, 3>& in,
    int zOffset,
    int halfWidth,
    int targetLength);
  /// Unbinds, and reports a GL error of the pass.
  bool End(vtkAVSVolumeTextures& textures, std::string& error);

  /// GL names of the averaged-extinction compute programs: pass 1's (classifying), passes 2 and
  /// 3's.
  unsigned int Program[2] = { 0, 0 };
  /// Classification and packing defines it was built with.
  std::string Defines;
  /// Pass 1's ring (WindowRing) it was built with.
  int Ring = 0;
};

#endif
