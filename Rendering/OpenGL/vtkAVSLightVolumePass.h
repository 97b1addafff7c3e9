/**
 * @class   vtkAVSLightVolumePass
 * @brief   the light volumes tube-marched on the GPU (private)
 *
 * The compute pass of avs_lightvolume_cs.glsl: for one light (in the data's frame), the
 * transmittance of each node of the light grid through the averaged extinction, weighted by the
 * table slice's log gain, into the light's channel of the packed light-volume textures
 * (vtkAVSVolumeTextures; channel c of texture t holds light 4 t + c, allocated once per size),
 * and the copies of the averaged extinction into the channel after the last light's and of the
 * extended model's fluence of lights of one colour into the one after that. The tube marching
 * goes over the tiles of the light grid given (SetTiles: those that the rays read,
 * avs::LightGridTiles; or a list written on the GPU, GetTiles), one work group each.
 * The CPU twin is Rendering/Core/LightVolume.cxx.
 */
#ifndef vtkAVSLightVolumePass_h
#define vtkAVSLightVolumePass_h

#include "Grid.h"
#include "LightVolume.h"
#include "Lights.h"
#include "vtkAVSTileList.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

class vtkAVSVolumeTextures;
class vtkTextureObject;

class vtkAVSLightVolumePass
{
public:
  vtkAVSLightVolumePass() = default;
  vtkAVSLightVolumePass(const vtkAVSLightVolumePass&) = delete;
  vtkAVSLightVolumePass& operator=(const vtkAVSLightVolumePass&) = delete;

  /// Builds the programs for tables of up to `maximumTauNodes` tau nodes, writing the light
  /// textures' format (vtkAVSVolumeTextures::LightVolumeFormat); false when it does not compile.
  bool Build(int maximumTauNodes, bool software);
  /// Runs the pass for light `index` (the caller checked for compute shaders, the averaged
  /// extinction on the light grid and a table slice of at most `maximumTauNodes` nodes); `law`
  /// as avs::ComputeLightVolume's.
  bool Run(vtkAVSVolumeTextures& textures,
    int index,
    const avs::GridGeometry& lightGrid,
    const avs::Light& light,
    double radius,
    avs::TubeLaw law,
    std::string& error);
  /// Copies the averaged extinction into slot `slot` of the packed textures (channel slot % 4
  /// of texture slot / 4, which holds no light), where the ray caster reads it with the tube
  /// transmittances: one texture fetch per sample fewer for 1-3 and 5-7 lights. Records it in
  /// vtkAVSVolumeTextures::AveragedSlot.
  bool CopyAveraged(vtkAVSVolumeTextures& textures, int slot, std::string& error);
  /// Copies the extended model's diffuse fluence `fluence` (RGBA on the light grid:
  /// vtkAVSDiffuseVolume) of lights of the one colour `colour` (avs::CommonColour) into slot
  /// `slot` as one number per point, phi.c / c.c, which the ray caster multiplies by c: the
  /// fluence read in the lights' fetch, one fetch per pair of samples fewer for 1, 2, 5 or 6
  /// lights. Records it in vtkAVSVolumeTextures::PhiSlot with `writes`.
  bool CopyFluence(vtkAVSVolumeTextures& textures,
    int slot,
    vtkTextureObject* fluence,
    int writes,
    const avs::Vec3& colour,
    std::string& error);
  /// The tiles of the light grid `dimensions` that Run marches (avs::LightGridTiles; every tile
  /// where none were set for the grid Run is given), uploaded where they differ from the last
  /// ones (the context current); false with the reason when the upload fails.
  bool SetTiles(const std::array<int, 3>& dimensions,
    const std::vector<std::uint32_t>& tiles,
    std::string& error);
  /// The tiles Run marches, for a list written on the GPU (vtkAVSDiffuseVolume::MarkTiles).
  vtkAVSTileList& GetTiles() { return this->Tiles; }
  /// Forgets the program and the tiles' buffer, deleting them when their context is current
  /// (`context`).
  void ReleaseGraphicsResources(bool context);

private:
  /// The programs: tube marching from a directional light, from a positional one, the
  /// averaged extinction's copy and the fluence's (one each: a software rasterizer runs every
  /// branch of a shader, so a copy would pay for a march).
  enum Variant
  {
    Directional,
    Positional,
    Copy,
    CopyFluenceVariant,
    NumberOfVariants
  };
  /// The program over the light grid into slot `slot` of the packed textures (channel slot % 4
  /// of texture slot / 4): tube marching, or the averaged extinction's copy; `uniforms` sets
  /// what the pass needs beyond the target, the channel and the averaged extinction. `what`
  /// names the pass in a GL error.
  bool Dispatch(vtkAVSVolumeTextures& textures,
    int slot,
    Variant variant,
    const std::function<void(const std::function<int(const char*)>&)>& uniforms,
    const char* what,
    std::string& error);
  /// GL names of the light-volume compute programs, one per Variant.
  unsigned int Programs[NumberOfVariants] = { 0, 0, 0, 0 };
  vtkAVSTileList Tiles; ///< what Run marches (SetTiles)
};

#endif
