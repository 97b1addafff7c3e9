/**
 * @class   vtkAVSShaderAssembly
 * @brief   the ray caster's GLSL programs put together from the shader snippets (private)
 *
 * The ray-casting fragment shader is avs_raycast_fs.glsl with the classification
 * (avs_classify.glsl), the lights (avs_lights.glsl), the clipping (avs_clip.glsl) and one effect
 * file (avs_ea_effect.glsl, avs_blend_effect.glsl, avs_ao_effect.glsl or avs_as_effect.glsl,
 * split at its //AVS::Effect::Init, //AVS::Effect::Pair and //AVS::Effect::Sample markers) put
 * in at its markers, and empty-space skipping (avs_skip.glsl, where AVS_SKIP is defined),
 * after the frame's compile-time choices (RayCastDefines). The compute passes' sources get their
 * defines after the #version line; the averaged-extinction pass gets the same classification and
 * clipping snippets as the ray caster, so the two cannot drift apart.
 */
#ifndef vtkAVSShaderAssembly_h
#define vtkAVSShaderAssembly_h

#include "Lights.h"
#include "ReferenceRenderer.h"
#include "ScatteringParameters.h"
#include "vtkAVSClassification.h"

#include <string>
#include <vector>

class vtkAVSShaderAssembly
{
public:
  /// Ambient scattering's ring buffer of the look-ahead (entries), 0 where the radius needs
  /// more than vtkAVSRayCaster::MaximumRingSize (the explicit look-ahead).
  static int RingSize(const avs::ScatteringParameters& parameters);
  /// Compile-time choices of the ray-casting program for a frame (see avs_lights.glsl and the
  /// effect files): the classification's, the number of lights and which are positional or
  /// spots, AO's direct light, and for ambient scattering the ring buffer's size (or the explicit
  /// look-ahead), the diffuse fluence, the light textures to fetch, emission and the per-ray table
  /// columns of directional lights (`tauNodes`: the table slice's tau axis), and where the
  /// averaged extinction is read (`averagedSlot`: the light-texture slot that holds a copy of
  /// it, vtkAVSVolumeTextures::AveragedSlot, or -1 for its own texture), where the extended
  /// model's fluence of lights of one colour is (`phiSlot`, vtkAVSVolumeTextures::PhiSlot: with
  /// `averagedSlot`, the rays read neither from the fluence's texture), and whether the lights
  /// are read once per group of `lightGroup` samples (1, 2 or 4,
  /// avs::ScatteringParameters::LightGroup).
  /// One program per combination.
  static std::string RayCastDefines(avs::RenderMode mode,
    const avs::ScatteringParameters& parameters,
    const std::vector<avs::Light>& lights,
    int tauNodes,
    const vtkAVSClassification::Layout& layout,
    int averagedSlot = -1,
    int phiSlot = -1,
    int lightGroup = 1);
  /// The ray-casting fragment shader of `mode` with `defines` (RayCastDefines, the clipping's and
  /// the blend mode's); a blend mode other than composite (AVS_BLEND) takes the blend effect.
  static std::string RayCastFragmentShader(avs::RenderMode mode, const std::string& defines);
  /// The image sampler's compositing fragment shader (avs_upsample_fs.glsl) with the display
  /// transform.
  static std::string UpsampleFragmentShader();
  /// The path tracer of the refinement (avs_pathtrace_fs.glsl) with `defines` (the ray
  /// caster's, for its classification, lights and clipping) and the snippets they choose.
  static std::string PathTraceFragmentShader(const std::string& defines);
  /// The refinement's picture (avs_refine_fs.glsl) with the display transform.
  static std::string RefineFragmentShader();

  /// The averaged-extinction compute shader (avs_average_cs.glsl) with `defines` and the
  /// classification and clipping snippets.
  static std::string AveragedExtinctionShader(const std::string& defines);
  /// The light-volume compute shader (avs_lightvolume_cs.glsl) for tables of up to
  /// `maximumTauNodes` tau nodes, writing light volumes of 32-bit floats (`software`) or half
  /// floats; `variant`: its defines for one kind of pass (the shader says which).
  static std::string LightVolumeShader(int maximumTauNodes,
    bool software,
    const std::string& variant);
  /// Compiles and links a compute program (the context current); 0, with a warning naming
  /// `what`, when it does not compile or link.
  static unsigned int BuildComputeProgram(const char* source, const char* what);
  /// Deletes a compute program when the context that made it is current (`context`), and
  /// forgets its name either way (a deleted window's context took it with it).
  static void ReleaseComputeProgram(unsigned int& program, bool context);
};

#endif
