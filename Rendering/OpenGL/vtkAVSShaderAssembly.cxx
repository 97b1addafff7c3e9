#include "vtkAVSShaderAssembly.h"

#include "vtkAVSRayCaster.h"
#include "vtkAVSShaders.h"
#include "vtkAVSVolumeTextures.h"

#include "vtkAVSOpenGL.h"
#include "vtkObject.h" // for vtkGenericWarningMacro

#include <algorithm>
#include <cmath>

namespace
{
// Splits an effect file into its declarations, its per-ray set-up (optional), its per-pair code
// (optional; avs_raycast_fs.glsl, AVS_SAMPLE_PAIRS) and its per-sample code, in that order.
void SplitEffect(const std::string& text,
  std::string& dec,
  std::string& init,
  std::string& pair,
  std::string& sample)
{
  const std::string initMarker = "//AVS::Effect::Init";
  const std::string pairMarker = "//AVS::Effect::Pair";
  const std::string sampleMarker = "//AVS::Effect::Sample";
  const std::size_t sampleAt = std::min(text.find(sampleMarker), text.size());
  const std::size_t pairAt = std::min(text.find(pairMarker), sampleAt);
  const std::size_t initAt = std::min(text.find(initMarker), pairAt);
  dec = text.substr(0, initAt);
  init = initAt < pairAt
    ? text.substr(initAt + initMarker.size(), pairAt - initAt - initMarker.size())
    : std::string();
  pair = pairAt < sampleAt
    ? text.substr(pairAt + pairMarker.size(), sampleAt - pairAt - pairMarker.size())
    : std::string();
  sample = sampleAt < text.size() ? text.substr(sampleAt + sampleMarker.size()) : std::string();
}

void Replace(std::string& s, const std::string& what, const std::string& with)
{
  const std::size_t at = s.find(what);
  if (at != std::string::npos)
  {
    s.replace(at, what.size(), with);
  }
}
} // namespace

int vtkAVSShaderAssembly::RingSize(const avs::ScatteringParameters& p)
{
  // A ray of two or more steps has dt >= sample distance / 2, so the look-ahead k = floor(r /
  // dt), which needs k + 2 entries, is at most 2 r / sample distance; a ray of one step adds no
  // in-scattered light.
  const double most = 2.0 * p.AmbientRadius / p.SampleDistance + 2.0;
  int ring = 16;
  while (ring < most && ring <= vtkAVSRayCaster::MaximumRingSize)
  {
    ring *= 2;
  }
  return ring > vtkAVSRayCaster::MaximumRingSize ? 0 : ring;
}

std::string vtkAVSShaderAssembly::RayCastDefines(avs::RenderMode mode,
  const avs::ScatteringParameters& p,
  const std::vector<avs::Light>& lights,
  int tauNodes,
  const vtkAVSClassification::Layout& layout,
  int averagedSlot,
  int phiSlot,
  int lightGroup)
{
  // The classification's choices (avs_classify.glsl).
  std::string defines = layout.Defines();
  if (mode == avs::RenderMode::EmissionAbsorption)
  {
    return defines;
  }
  defines += "#define AVS_NUMBER_OF_LIGHTS " + std::to_string(lights.size()) + "\n";
  int positional = 0;
  for (std::size_t j = 0; j < lights.size(); ++j)
  {
    positional |= lights[j].Type == avs::LightType::Positional ? 1 << j : 0;
  }
  defines += "#define AVS_POSITIONAL_LIGHTS " + std::to_string(positional) + "\n";
  if (std::any_of(lights.begin(), lights.end(), [](const avs::Light& l) { return l.IsSpot(); }))
  {
    defines += "#define AVS_SPOT_LIGHTS\n";
  }
  if (mode == avs::RenderMode::AmbientOcclusion)
  {
    if (p.DirectLightWeight > 0.0 && !lights.empty())
    {
      defines += "#define AVS_DIRECT_LIGHT\n";
    }
    return defines;
  }
  const int ring = RingSize(p);
  defines += ring == 0 ? "#define AVS_LOOKAHEAD_EXPLICIT\n"
                       : "#define AVS_RING " + std::to_string(ring) + "\n";
  // The extended model: the diffuse fluence with the averaged extinction in one fetch
  // (vtkAVSDiffuseVolume), in place of the averaged extinction's.
  const bool extended = p.Model == avs::ScatteringModel::Extended;
  if (extended)
  {
    defines += "#define AVS_DIFFUSE\n";
    // With anisotropic scattering the diffuse field's flux along the ray counts too (phi's
    // derivative along the ray); with g = 0 it drops out, and with it a fetch and a division
    // per pair.
    if (p.Anisotropy != 0.0)
    {
      defines += "#define AVS_DIFFUSE_ANISOTROPIC\n";
    }
  }
  // Light-volume textures to fetch: lights 0-3, 4-7.
  const int n = static_cast<int>(lights.size());
  defines += "#define AVS_LIGHT_TEXTURES " +
    std::to_string(vtkAVSVolumeTextures::LightTexturesFor(n)) + "\n";
  // The averaged extinction in the free channel after the last light's, read with them; in the
  // extended model only with the fluence of lights of one colour in the channel after it (else
  // both are read from the fluence's texture).
  auto withLights = [n](int slot)
  {
    return slot >= 0 &&
      vtkAVSVolumeTextures::LightTexturesFor(slot + 1) == vtkAVSVolumeTextures::LightTexturesFor(n);
  };
  const bool fluenceSlot = extended && withLights(averagedSlot) && withLights(phiSlot);
  if (withLights(averagedSlot) && (!extended || fluenceSlot))
  {
    defines += "#define AVS_AVERAGED_SLOT " + std::to_string(averagedSlot) + "\n";
  }
  if (fluenceSlot)
  {
    defines += "#define AVS_PHI_SLOT " + std::to_string(phiSlot) + "\n";
  }
  if (p.EmissionWeight > 0.0 && p.Albedo < 1.0)
  {
    defines += "#define AVS_EMISSION\n";
  }
  if (lightGroup > 1)
  {
    defines += "#define AVS_LIGHTS_PER_PAIR\n#define AVS_LIGHT_GROUP " +
      std::to_string(lightGroup == 4 ? 4 : 2) + "\n";
  }
  // Surfaces inside the medium (avs_surface.glsl), their precomputed gradient in u_surfaces;
  // with a blending above 0 the share of surface events depends on each sample's opacity.
  if (p.Surface.Active())
  {
    defines += "#define AVS_SURFACE\n";
    if (p.Surface.Blending > 0.0)
    {
      defines += "#define AVS_SURFACE_BLENDED\n";
    }
    // An integer specular power (VTK's default 10) by squaring, which costs a software
    // rasterizer less than exp2 and log2.
    const double power = p.Surface.SpecularPower;
    if (power >= 0.0 && power <= 128.0 && power == std::floor(power))
    {
      defines +=
        "#define AVS_SURFACE_SPECULAR_POWER " + std::to_string(static_cast<int>(power)) + "\n";
    }
  }
  // Directional lights read A from a per-ray column of the table (see avs_as_effect.glsl) when
  // the table's tau axis is short enough to keep one column per light.
  if (positional != (1 << n) - 1 && tauNodes >= 2 && tauNodes <= vtkAVSRayCaster::MaximumTauNodes)
  {
    defines += "#define AVS_TABLE_COLUMN " + std::to_string(tauNodes) + "\n";
  }
  return defines;
}

std::string vtkAVSShaderAssembly::RayCastFragmentShader(avs::RenderMode mode,
  const std::string& defines)
{
  std::string fs = avs_raycast_fs;
  // Emission-absorption with a blend mode other than composite (vtkAVSShaderOptions).
  const bool blend = defines.find("#define AVS_BLEND ") != std::string::npos;
  std::string effect = mode == avs::RenderMode::EmissionAbsorption
    ? (blend ? avs_blend_effect : avs_ea_effect)
    : (mode == avs::RenderMode::AmbientOcclusion ? avs_ao_effect : avs_as_effect);
  std::string dec, init, pair, sample;
  SplitEffect(effect, dec, init, pair, sample);
  // The compile-time choices go before the first snippet that may test them.
  Replace(fs, "//AVS::Classify::Dec", defines + avs_classify);
  Replace(fs, "//AVS::Lights::Dec", avs_lights);
  Replace(fs, "//AVS::Display::Dec", avs_display);
  Replace(fs, "//AVS::Clip::Dec", avs_clip);
  Replace(fs, "//AVS::Effect::Dec", dec);
  Replace(fs, "//AVS::Surface::Dec", avs_surface);
  Replace(fs, "//AVS::Skip::Dec", avs_skip);
  Replace(fs, "//AVS::Effect::Init", init);
  Replace(fs, "//AVS::Effect::Pair", pair);
  Replace(fs, "//AVS::Effect::Sample", sample);
  return fs;
}

std::string vtkAVSShaderAssembly::UpsampleFragmentShader()
{
  std::string fs = avs_upsample_fs;
  Replace(fs, "//AVS::Display::Dec", avs_display);
  return fs;
}

std::string vtkAVSShaderAssembly::PathTraceFragmentShader(const std::string& defines)
{
  std::string fs = avs_pathtrace_fs;
  Replace(fs, "//AVS::Classify::Dec", defines + avs_classify);
  Replace(fs, "//AVS::Lights::Dec", avs_lights);
  Replace(fs, "//AVS::Clip::Dec", avs_clip);
  Replace(fs, "//AVS::Surface::Dec", avs_surface);
  return fs;
}

std::string vtkAVSShaderAssembly::RefineFragmentShader()
{
  std::string fs = avs_refine_fs;
  Replace(fs, "//AVS::Display::Dec", avs_display);
  return fs;
}

std::string vtkAVSShaderAssembly::AveragedExtinctionShader(const std::string& defines)
{
  std::string average = avs_average_cs;
  const std::size_t line = average.find('\n') + 1; // after #version
  average.insert(line, defines);
  Replace(average, "//AVS::Classify::Dec", avs_classify);
  Replace(average, "//AVS::Clip::Dec", avs_clip);
  return average;
}

std::string vtkAVSShaderAssembly::LightVolumeShader(int maximumTauNodes,
  bool software,
  const std::string& variant)
{
  // The light-volume pass keeps the table's log gain in an array of this many entries.
  std::string lightVolume = avs_lightvolume_cs;
  const std::size_t line = lightVolume.find('\n') + 1; // after #version
  lightVolume.insert(line,
    "#define AVS_MAXIMUM_TAU_NODES " + std::to_string(maximumTauNodes) + "\n" +
      "#define AVS_LIGHT_FORMAT " + (software ? "rgba32f" : "rgba16f") + "\n" + variant);
  return lightVolume;
}

unsigned int vtkAVSShaderAssembly::BuildComputeProgram(const char* source, const char* what)
{
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
  {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof(log) - 1, nullptr, log);
    vtkGenericWarningMacro("The " << what << " compute shader did not compile. " << log);
    glDeleteShader(shader);
    return 0;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
  {
    glDeleteProgram(program);
    return 0;
  }
  return program;
}

void vtkAVSShaderAssembly::ReleaseComputeProgram(unsigned int& program, bool context)
{
  if (program && context)
  {
    glDeleteProgram(program);
  }
  program = 0;
}
