#include "vtkAVSLightVolumePass.h"

#include "vtkAVSRenderPasses.h"
#include "vtkAVSShaderAssembly.h"
#include "vtkAVSVolumeTextures.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkTextureObject.h"

#include "LightTiles.h"

#include <algorithm>
#include <array>
#include <functional>

bool vtkAVSLightVolumePass::Build(int maximumTauNodes, bool software)
{
  const char* variants[NumberOfVariants] = { "",
    "#define AVS_LIGHT_VOLUME_POSITIONAL\n",
    "#define AVS_LIGHT_VOLUME_COPY\n",
    "#define AVS_LIGHT_VOLUME_COPY_FLUENCE\n" };
  for (int v = 0; v < NumberOfVariants; ++v)
  {
    this->Programs[v] = vtkAVSShaderAssembly::BuildComputeProgram(
      vtkAVSShaderAssembly::LightVolumeShader(maximumTauNodes, software, variants[v]).c_str(),
      "light-volume");
    if (!this->Programs[v])
    {
      this->ReleaseGraphicsResources(true);
      return false;
    }
  }
  return true;
}

void vtkAVSLightVolumePass::ReleaseGraphicsResources(bool context)
{
  for (unsigned int& program : this->Programs)
  {
    vtkAVSShaderAssembly::ReleaseComputeProgram(program, context);
  }
  this->Tiles.ReleaseGraphicsResources(context);
}

bool vtkAVSLightVolumePass::SetTiles(const std::array<int, 3>& dimensions,
  const std::vector<std::uint32_t>& tiles,
  std::string& error)
{
  if (!this->Tiles.Set(dimensions, tiles, error))
  {
    error = "the light-volume pass: " + error;
    return false;
  }
  return true;
}

bool vtkAVSLightVolumePass::Dispatch(vtkAVSVolumeTextures& textures,
  int slot,
  Variant variant,
  const std::function<void(const std::function<int(const char*)>&)>& uniforms,
  const char* what,
  std::string& error)
{
  const std::array<int, 3> d = textures.LightTextureDimensions;
  const GLuint program = this->Programs[variant];
  vtkAVSRenderPasses::DiscardErrors(); // the check at the end is of this pass alone
  // The shader cache must rebind its own program afterwards.
  textures.Window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(program);
  const std::function<int(const char*)> location = [program](const char* name)
  { return glGetUniformLocation(program, name); };
  // Channel c of texture t holds slot 4 t + c.
  glBindImageTexture(0,
    textures.LightVolumes[slot / 4]->GetHandle(),
    0,
    GL_TRUE,
    0,
    GL_READ_WRITE,
    textures.LightVolumeFormat());
  glUniform1i(location("u_channel"), slot % 4);
  glUniform3i(location("u_targetDimensions"), d[0], d[1], d[2]);
  textures.AveragedExtinction->Activate();
  glUniform1i(location("u_averaged"), textures.AveragedExtinction->GetTextureUnit());
  uniforms(location);
  if (variant == Directional || variant == Positional)
  {
    // Tube marching: one work group per tile (SetTiles, or a list written on the GPU).
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    this->Tiles.Dispatch(0);
  }
  else
  {
    glDispatchCompute(static_cast<GLuint>((d[0] + 7) / 8),
      static_cast<GLuint>((d[1] + 7) / 8),
      static_cast<GLuint>(d[2]));
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_WRITE, textures.LightVolumeFormat());
  glUseProgram(0);
  textures.AveragedExtinction->Deactivate();
  if (const GLenum status = glGetError())
  {
    error = std::string(what) + " failed (GL error " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

bool vtkAVSLightVolumePass::Run(vtkAVSVolumeTextures& textures,
  int index,
  const avs::GridGeometry& lightGrid,
  const avs::Light& light,
  double radius,
  avs::TubeLaw law,
  std::string& error)
{
  if (!textures.EnsureLightTextures(lightGrid.Dimensions, index / 4 + 1, error))
  {
    return false;
  }
  if (!this->Tiles.IsOf(lightGrid.Dimensions) &&
    !this->SetTiles(lightGrid.Dimensions, avs::AllLightTiles(lightGrid.Dimensions), error))
  {
    return false;
  }
  if (index == textures.AveragedSlot)
  {
    textures.AveragedSlot = -1; // overwritten
  }
  if (index == textures.PhiSlot)
  {
    textures.PhiSlot = -1;
  }
  auto uniforms = [&](const std::function<int(const char*)>& location)
  {
    glUniform3f(location("u_targetSpacing"),
      static_cast<float>(lightGrid.Spacing.x),
      static_cast<float>(lightGrid.Spacing.y),
      static_cast<float>(lightGrid.Spacing.z));
    const avs::Vec3 extent = lightGrid.LocalExtent();
    glUniform3f(location("u_extent"),
      static_cast<float>(extent.x),
      static_cast<float>(extent.y),
      static_cast<float>(extent.z));
    glUniform1fv(location("u_logGain"),
      static_cast<GLsizei>(textures.LogGain.size()),
      textures.LogGain.data());
    glUniform1i(location("u_tauNodes"), static_cast<GLint>(textures.LogGain.size()));
    glUniform1f(location("u_tauMaximum"), textures.TableTauMaximum);
    glUniform1f(location("u_radius"), static_cast<float>(radius));
    glUniform1i(location("u_directBeam"), law == avs::TubeLaw::DirectBeam ? 1 : 0);
    const bool positional = light.Type == avs::LightType::Positional;
    const avs::Vec3 l = positional
      ? lightGrid.WorldToLocal(light.Position)
      : lightGrid.WorldToLocalDirection(avs::Normalize(light.FocalPoint - light.Position));
    glUniform3f(location("u_light"),
      static_cast<float>(l.x),
      static_cast<float>(l.y),
      static_cast<float>(l.z));
  };
  return this->Dispatch(textures,
    index,
    light.Type == avs::LightType::Positional ? Positional : Directional,
    uniforms,
    "the light-volume compute pass",
    error);
}

bool vtkAVSLightVolumePass::CopyAveraged(vtkAVSVolumeTextures& textures,
  int slot,
  std::string& error)
{
  const int texture = slot / 4;
  if (slot < 0 || texture >= vtkAVSVolumeTextures::NumberOfLightTextures ||
    !textures.LightVolumes[texture] || !textures.AveragedExtinction)
  {
    error = "no light-volume channel to hold the averaged extinction";
    return false;
  }
  if (!this->Dispatch(
        textures,
        slot,
        Copy,
        [](const std::function<int(const char*)>&) {},
        "copying the averaged extinction",
        error))
  {
    return false;
  }
  textures.AveragedSlot = slot;
  textures.AveragedSlotWrites = textures.AveragedWrites;
  if (slot == textures.PhiSlot)
  {
    textures.PhiSlot = -1; // overwritten
  }
  return true;
}

bool vtkAVSLightVolumePass::CopyFluence(vtkAVSVolumeTextures& textures,
  int slot,
  vtkTextureObject* fluence,
  int writes,
  const avs::Vec3& colour,
  std::string& error)
{
  const int texture = slot / 4;
  const double norm = avs::Dot(colour, colour);
  if (slot < 0 || texture >= vtkAVSVolumeTextures::NumberOfLightTextures ||
    !textures.LightVolumes[texture] || !textures.AveragedExtinction || !fluence || !(norm > 0.0))
  {
    error = "no light-volume channel to hold the diffuse fluence";
    return false;
  }
  if (slot == textures.AveragedSlot)
  {
    textures.AveragedSlot = -1; // overwritten
  }
  textures.PhiSlot = -1;
  fluence->Activate();
  const bool ok = this->Dispatch(
    textures,
    slot,
    CopyFluenceVariant,
    [&](const std::function<int(const char*)>& location)
    {
      glUniform1i(location("u_fluence"), fluence->GetTextureUnit());
      glUniform3f(location("u_fluenceWeights"),
        static_cast<float>(colour.x / norm),
        static_cast<float>(colour.y / norm),
        static_cast<float>(colour.z / norm));
    },
    "copying the diffuse fluence",
    error);
  fluence->Deactivate();
  if (!ok)
  {
    return false;
  }
  textures.PhiSlot = slot;
  textures.PhiSlotWrites = writes;
  return true;
}
