#include "vtkAVSDiffuseVolume.h"

#include "DiffuseFluence.h"
#include "vtkAVSRenderPasses.h"
#include "vtkAVSShaderAssembly.h"
#include "vtkAVSShaders.h"
#include "vtkAVSTextureMemory.h"
#include "vtkAVSTextureUpload.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>

vtkAVSDiffuseVolume::vtkAVSDiffuseVolume() = default;

vtkAVSDiffuseVolume::~vtkAVSDiffuseVolume() = default;

bool vtkAVSDiffuseVolume::Upload(vtkOpenGLRenderWindow* window,
  const std::vector<avs::Grid>& phi,
  const avs::Grid& averaged,
  std::string& error)
{
  const std::size_t n = averaged.Values.size();
  if (phi.size() != 3 || n != averaged.Geometry.NumberOfPoints() ||
    std::any_of(phi.begin(),
      phi.end(),
      [&](const avs::Grid& g)
      { return g.Values.size() != n || g.Geometry.Dimensions != averaged.Geometry.Dimensions; }))
  {
    error = "the diffuse fluence is not three grids on the light grid";
    return false;
  }
  const std::array<int, 3> d = averaged.Geometry.Dimensions;
  std::vector<float> packed(4 * n, 0.0f);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      packed[4 * i + c] = phi[c].Values[i];
    }
    packed[4 * i + 3] = averaged.Values[i];
  }
  if (!this->Allocate(window, this->Texture, d, packed.data(), error))
  {
    return false;
  }
  this->Dimensions = d;
  ++this->Writes;
  return true;
}

bool vtkAVSDiffuseVolume::Allocate(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkTextureObject>& texture,
  const std::array<int, 3>& d,
  const float* data,
  std::string& error)
{
  std::vector<vtkTextureObject*> held =
    this->OtherTextures ? this->OtherTextures() : std::vector<vtkTextureObject*>();
  for (vtkTextureObject* t : this->GetTextures())
  {
    held.push_back(t); // (the one replaced is left out by the budget)
  }
  if (!vtkAVSTextureUpload::UploadFloats(window, texture, d, 4, data, GL_RGBA32F, held, error))
  {
    error = "the diffuse-fluence texture: " + error;
    return false;
  }
  return true;
}

bool vtkAVSDiffuseVolume::Compute(vtkOpenGLRenderWindow* window,
  const avs::GridGeometry& grid,
  const std::array<int, 3>& lightDimensions,
  vtkTextureObject* averaged,
  vtkTextureObject* lights0,
  vtkTextureObject* lights1,
  const std::vector<avs::Light>& lights,
  const avs::ScatteringParameters& p,
  std::string& error)
{
  const int n = static_cast<int>(std::min<std::size_t>(lights.size(), 8));
  if (!averaged || (n > 0 && !lights0) || (n > 4 && !lights1))
  {
    error = "the diffusion solve needs the averaged extinction and the light volumes on the GPU";
    return false;
  }
  // The program for these lights' kinds (avs_lights.glsl's defines).
  int positional = 0;
  bool spot = false;
  for (int j = 0; j < n; ++j)
  {
    if (lights[j].Type == avs::LightType::Positional)
    {
      positional |= 1 << j;
      spot = spot || lights[j].IsSpot();
    }
  }
  const std::string defines = "#define AVS_NUMBER_OF_LIGHTS " + std::to_string(n) +
    "\n#define AVS_POSITIONAL_LIGHTS " + std::to_string(positional) + "\n" +
    (spot ? "#define AVS_SPOT_LIGHTS\n" : "");
  if (!this->Programs[0] || defines != this->ProgramDefines)
  {
    this->ProgramDefines.clear();
    for (int stage = 0; stage < 3; ++stage)
    {
      vtkAVSShaderAssembly::ReleaseComputeProgram(this->Programs[stage], true);
      std::string source = avs_diffusion_cs;
      const std::size_t line = source.find('\n') + 1; // after #version
      source.insert(line,
        "#define AVS_DIFFUSION_STAGE " + std::to_string(stage) + "\n" + defines + avs_lights +
          "\n");
      this->Programs[stage] =
        vtkAVSShaderAssembly::BuildComputeProgram(source.c_str(), "diffusion");
      if (!this->Programs[stage])
      {
        error = "the diffusion compute shader did not build";
        return false;
      }
    }
    this->ProgramDefines = defines;
  }
  // The nested solve's levels (DiffusionLevels), finest first: the finest is the texture the
  // ray caster reads, the coarser ones are held with their sources for the next solve.
  const std::vector<avs::GridGeometry> levels = avs::DiffusionLevels(grid);
  for (std::size_t t = 2 * (levels.size() - 1); t < this->Coarser.size(); ++t)
  {
    if (this->Coarser[t])
    {
      this->Coarser[t]->ReleaseGraphicsResources(window);
    }
  }
  this->Coarser.resize(2 * (levels.size() - 1));
  for (std::size_t l = 0; l < levels.size(); ++l)
  {
    vtkSmartPointer<vtkTextureObject>& phi = this->LevelFluence(l);
    vtkSmartPointer<vtkTextureObject>& q = this->LevelSource(l);
    if (!this->Allocate(window, phi, levels[l].Dimensions, nullptr, error) ||
      !this->Allocate(window, q, levels[l].Dimensions, nullptr, error))
    {
      return false;
    }
  }
  if (!this->Allocate(window, this->Texture, lightDimensions, nullptr, error))
  {
    return false;
  }
  this->Dimensions = lightDimensions;

  vtkAVSRenderPasses::DiscardErrors();
  window->GetShaderCache()->ReleaseCurrentShader();
  GLuint program = 0;
  auto location = [&program](const char* name) { return glGetUniformLocation(program, name); };
  auto use = [&program](GLuint which)
  {
    program = which;
    glUseProgram(program);
  };
  // Lights in the data's local frame (a rigid map of the data's frame: distances and cones
  // stay).
  float position[8][3] = {}, axis[8][3] = {}, irradiance[8][3] = {}, attenuation[8][3] = {};
  float coneCos[8] = {}, exponent[8] = {}, weight[8] = {};
  for (int j = 0; j < n; ++j)
  {
    const avs::Light& l = lights[j];
    const avs::Vec3 x = grid.WorldToLocal(l.Position);
    const avs::Vec3 a = grid.WorldToLocalDirection(avs::Normalize(l.FocalPoint - l.Position));
    for (int k = 0; k < 3; ++k)
    {
      position[j][k] = static_cast<float>(x[k]);
      axis[j][k] = static_cast<float>(a[k]);
      irradiance[j][k] = static_cast<float>(l.Irradiance[k]);
      attenuation[j][k] = static_cast<float>(l.Attenuation[k]);
    }
    coneCos[j] = l.IsSpot() ? static_cast<float>(std::cos(l.ConeAngle * avs::Pi / 180.0)) : -2.0f;
    exponent[j] = l.IsSpot() ? static_cast<float>(l.Exponent) : 0.0f;
    const avs::TubeLaw law = avs::TubeLawFor(true, l.Type);
    weight[j] = static_cast<float>(avs::DiffusionSourceWeight(law, p.Albedo, p.Anisotropy));
  }
  averaged->Activate();
  vtkTextureObject* first = lights0 ? lights0 : averaged;
  vtkTextureObject* second = lights1 ? lights1 : first;
  first->Activate();
  if (second != first)
  {
    second->Activate();
  }
  // What every stage reads: the lights, the model's parameters and the textures.
  for (const GLuint stage : this->Programs)
  {
    use(stage);
    glUniform3fv(location("u_lightPosition"), 8, &position[0][0]);
    glUniform3fv(location("u_lightAxis"), 8, &axis[0][0]);
    glUniform3fv(location("u_lightIrradiance"), 8, &irradiance[0][0]);
    glUniform3fv(location("u_lightAttenuation"), 8, &attenuation[0][0]);
    glUniform1fv(location("u_lightConeCos"), 8, coneCos);
    glUniform1fv(location("u_lightExponent"), 8, exponent);
    glUniform1fv(location("u_sourceWeight"), 8, weight);
    glUniform3f(location("u_lightDimensions"),
      static_cast<float>(lightDimensions[0]),
      static_cast<float>(lightDimensions[1]),
      static_cast<float>(lightDimensions[2]));
    glUniform1f(location("u_albedo"), static_cast<float>(p.Albedo));
    glUniform1f(location("u_anisotropy"), static_cast<float>(p.Anisotropy));
    glUniform1f(location("u_ambientRadius"), static_cast<float>(p.AmbientRadius));
    glUniform1f(location("u_relaxation"), static_cast<float>(avs::DiffusionSettings().Relaxation));
    glUniform1f(location("u_transportLimit"),
      static_cast<float>(avs::TransportLengthLimitInRadii * p.AmbientRadius));
    glUniform1i(location("u_averaged"), averaged->GetTextureUnit());
    glUniform1i(location("u_lightVolumes0"), first->GetTextureUnit());
    glUniform1i(location("u_lightVolumes1"), second->GetTextureUnit());
  }
  // Coarsest level first; each starts from the coarser one's phi (the shader's Coarser), with
  // DiffusionCoarseIterations sweeps, the finest with DiffusionIterations.
  for (std::size_t l = levels.size(); l-- > 0;)
  {
    const avs::GridGeometry& level = levels[l];
    const std::array<int, 3>& n = level.Dimensions;
    vtkTextureObject* phi = this->LevelFluence(l);
    vtkTextureObject* q = this->LevelSource(l);
    vtkTextureObject* coarser = l + 1 < levels.size() ? this->LevelFluence(l + 1).Get() : phi;
    // The level's grid, for its source (stage 0) and its sweeps (stage 1).
    for (int stage = 1; stage >= 0; --stage)
    {
      use(this->Programs[stage]);
      glUniform3i(location("u_dimensions"), n[0], n[1], n[2]);
      glUniform3f(location("u_spacing"),
        static_cast<float>(level.Spacing.x),
        static_cast<float>(level.Spacing.y),
        static_cast<float>(level.Spacing.z));
      glUniform1f(location("u_vacuum"),
        static_cast<float>(
          avs::VacuumOpticalDepth * 3.0 / (level.Spacing.x + level.Spacing.y + level.Spacing.z)));
      glUniform1i(location("u_hasCoarser"), l + 1 < levels.size() ? 1 : 0);
      const std::array<int, 3> c = l + 1 < levels.size() ? levels[l + 1].Dimensions : n;
      glUniform3i(location("u_coarserDimensions"), c[0], c[1], c[2]);
    }
    glBindImageTexture(0, phi->GetHandle(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(1, q->GetHandle(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(2, coarser->GetHandle(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    const GLuint groups[3] = { static_cast<GLuint>((n[0] + 7) / 8),
      static_cast<GLuint>((n[1] + 7) / 8),
      static_cast<GLuint>(n[2]) };
    glDispatchCompute(groups[0], groups[1], groups[2]);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    use(this->Programs[1]);
    // A half-sweep's invocations cover every other cell of a row (the shader's main).
    const GLuint halfRow = static_cast<GLuint>(((n[0] + 1) / 2 + 7) / 8);
    const int sweeps = l == 0 ? p.DiffusionIterations : p.DiffusionCoarseIterations;
    for (int it = 0; it < sweeps; ++it)
    {
      for (int colour = 0; colour < 2; ++colour)
      {
        glUniform1i(location("u_colour"), colour);
        glDispatchCompute(halfRow, groups[1], groups[2]);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      }
    }
  }
  // phi onto the light grid, with the averaged extinction, for the ray caster's one fetch.
  {
    const std::array<int, 3>& n = lightDimensions;
    const std::array<int, 3>& m = grid.Dimensions;
    use(this->Programs[2]);
    glUniform3i(location("u_dimensions"), n[0], n[1], n[2]);
    glUniform3i(location("u_coarserDimensions"), m[0], m[1], m[2]);
    glBindImageTexture(2, this->Fluence->GetHandle(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(3, this->Texture->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(static_cast<GLuint>((n[0] + 7) / 8),
      static_cast<GLuint>((n[1] + 7) / 8),
      static_cast<GLuint>(n[2]));
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(1, 0, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(2, 0, 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(3, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glUseProgram(0);
  averaged->Deactivate();
  first->Deactivate();
  if (second != first)
  {
    second->Deactivate();
  }
  if (const GLenum status = glGetError())
  {
    error = "OpenGL error " + std::to_string(status) + " in the diffusion solve";
    return false;
  }
  ++this->Writes;
  return true;
}

double vtkAVSDiffuseVolume::HeldBytes() const
{
  double bytes = 0.0;
  for (vtkTextureObject* t : this->GetTextures())
  {
    bytes += vtkAVSTextureMemory::Bytes(t);
  }
  return bytes;
}

std::vector<vtkTextureObject*> vtkAVSDiffuseVolume::GetTextures() const
{
  std::vector<vtkTextureObject*> textures = { this->Texture, this->Fluence, this->Source };
  for (vtkTextureObject* t : this->Coarser)
  {
    textures.push_back(t);
  }
  return textures;
}

void vtkAVSDiffuseVolume::Bind(vtkShaderProgram* program,
  const avs::ScatteringParameters& p,
  const avs::Vec3* colour)
{
  if (!this->Texture)
  {
    return;
  }
  if (colour)
  {
    const float c[3] = {
      static_cast<float>(colour->x), static_cast<float>(colour->y), static_cast<float>(colour->z)
    };
    program->SetUniform3f("u_phiColour", c);
  }
  else
  {
    this->Texture->Activate();
    program->SetUniformi("u_diffuse", this->Texture->GetTextureUnit());
  }
  program->SetUniformf("u_anisotropy", static_cast<float>(p.Anisotropy));
  program->SetUniformf("u_reducedFloor",
    static_cast<float>(1.0 / std::max(1e-30, avs::TransportLengthLimitInRadii * p.AmbientRadius)));
}

void vtkAVSDiffuseVolume::Unbind()
{
  if (this->Texture && this->Texture->GetTextureUnit() >= 0)
  {
    this->Texture->Deactivate();
  }
}

void vtkAVSDiffuseVolume::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Coarser.push_back(this->Texture);
  this->Coarser.push_back(this->Fluence);
  this->Coarser.push_back(this->Source);
  for (vtkSmartPointer<vtkTextureObject>& t : this->Coarser)
  {
    if (t)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  this->Coarser.clear();
  this->Texture = nullptr;
  this->Fluence = nullptr;
  this->Source = nullptr;
  // Without a window its context took the program with it: the name is only forgotten.
  for (unsigned int& program : this->Programs)
  {
    vtkAVSShaderAssembly::ReleaseComputeProgram(program, window != nullptr);
  }
  this->ProgramDefines.clear();
  this->Dimensions = { 0, 0, 0 };
}
