/**
 * @class   vtkAVSShaderOptions
 * @brief   clipping, cropping and blend modes as the ray caster's shaders take them (private)
 *
 * The clip region (Core/ClipRegion.h) becomes compile-time choices and uniforms of
 * avs_clip.glsl, for the ray-casting program and the averaged-extinction compute pass; the
 * emission-absorption blend modes other than composite become the choices and uniforms of
 * avs_blend_effect.glsl.
 */
#ifndef vtkAVSShaderOptions_h
#define vtkAVSShaderOptions_h

#include "ClipRegion.h"

#include <string>
#include <vector>

class vtkShaderProgram;

class vtkAVSShaderOptions
{
public:
  /// What vtkVolumeMapper's blend mode asks of the emission-absorption ray caster.
  struct Blend
  {
    int Mode = 0;                             ///< vtkVolumeMapper::BlendModes
    double ScalarRange[2] = { 0.0, 1.0 };     ///< the data's, which scalars are normalised over
    double AverageRange[2] = { -1e38, 1e38 }; ///< AverageIPScalarRange
    std::vector<double> IsoValues;            ///< sorted, for ISOSURFACE_BLEND
  };
  /// Blend modes the emission-absorption ray caster renders besides composite: maximum,
  /// minimum and average intensity, additive, isosurface (vtkVolumeMapper's numbers).
  static bool IsSupportedBlend(int mode);
  /// "maximum intensity" and so on, for messages.
  static const char* BlendModeName(int mode);

  /// "#define AVS_CLIPPING" (planes or cropping) and "#define AVS_CROPPING" as needed.
  static std::string ClipDefines(const avs::ClipRegion& region);
  /// The uniforms of avs_clip.glsl, to a VTK shader program or (compute passes) a GL program.
  static void SetClipUniforms(vtkShaderProgram* program, const avs::ClipRegion& region);
  static void SetClipUniforms(unsigned int glProgram, const avs::ClipRegion& region);

  /// The defines of avs_blend_effect.glsl for a blend mode other than composite.
  static std::string BlendDefines(const Blend& blend);
  static void SetBlendUniforms(vtkShaderProgram* program, const Blend& blend);

private:
  struct ClipUniforms;
  static ClipUniforms Pack(const avs::ClipRegion& region);
};

#endif
