#include "vtkAVSDiffuseVolume.h"

#include "DiffuseFluence.h"
#include "LightTiles.h"
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

namespace
{
// The lists of level l of `levels` in the buffer of cells: the first entry, and each list's
// length (half its cells and one).
std::size_t ListCapacity(const avs::GridGeometry& level)
{
  const std::array<int, 3>& n = level.Dimensions;
  return static_cast<std::size_t>(n[0]) * n[1] * n[2] / 2 + 1;
}
std::size_t ListBase(const std::vector<avs::GridGeometry>& levels, std::size_t l)
{
  std::size_t base = 0;
  for (std::size_t k = 0; k < l; ++k)
  {
    base += 8 + 2 * ListCapacity(levels[k]);
  }
  return base;
}
} // namespace

bool vtkAVSDiffuseVolume::EnsurePrograms(const std::vector<avs::Light>* lights, std::string& error)
{
  // The source's program for these lights' kinds (avs_lights.glsl's defines; without lights it
  // is left as it is); the other stages have no lights.
  const int n = lights ? static_cast<int>(std::min<std::size_t>(lights->size(), 8)) : 0;
  int positional = 0;
  bool spot = false;
  for (int j = 0; j < n; ++j)
  {
    if ((*lights)[j].Type == avs::LightType::Positional)
    {
      positional |= 1 << j;
      spot = spot || (*lights)[j].IsSpot();
    }
  }
  const std::string defines = "#define AVS_NUMBER_OF_LIGHTS " + std::to_string(n) +
    "\n#define AVS_POSITIONAL_LIGHTS " + std::to_string(positional) + "\n" +
    (spot ? "#define AVS_SPOT_LIGHTS\n" : "");
  for (int stage = 0; stage < NumberOfStages; ++stage)
  {
    const bool withLights = stage == SourceStage;
    if ((withLights && !lights) ||
      (this->Programs[stage] && (!withLights || defines == this->ProgramDefines)))
    {
      continue;
    }
    vtkAVSShaderAssembly::ReleaseComputeProgram(this->Programs[stage], true);
    std::string source = avs_diffusion_cs;
    const std::size_t line = source.find('\n') + 1; // after #version
    source.insert(line,
      "#define AVS_DIFFUSION_STAGE " + std::to_string(stage) + "\n" +
        (withLights ? defines
                    : "#define AVS_NUMBER_OF_LIGHTS 0\n#define AVS_POSITIONAL_LIGHTS 0\n") +
        avs_lights + "\n");
    this->Programs[stage] = vtkAVSShaderAssembly::BuildComputeProgram(source.c_str(), "diffusion");
    if (!this->Programs[stage])
    {
      error = "the diffusion compute shader did not build";
      return false;
    }
    if (withLights)
    {
      this->ProgramDefines = defines;
    }
  }
  return true;
}

bool vtkAVSDiffuseVolume::ListCells(vtkOpenGLRenderWindow* window,
  const avs::GridGeometry& grid,
  const std::array<int, 3>& lightDimensions,
  vtkTextureObject* averaged,
  const std::vector<avs::Light>* lights,
  const avs::ScatteringParameters& p,
  int averagedVersion,
  std::string& error)
{
  const std::vector<avs::GridGeometry> levels = avs::DiffusionLevels(grid);
  const std::array<int, 3>& finest = levels[0].Dimensions;
  const std::vector<double> key{ static_cast<double>(averagedVersion),
    static_cast<double>(finest[0]),
    static_cast<double>(finest[1]),
    static_cast<double>(finest[2]),
    grid.Spacing.x,
    grid.Spacing.y,
    grid.Spacing.z,
    static_cast<double>(lightDimensions[0]),
    static_cast<double>(lightDimensions[1]),
    static_cast<double>(lightDimensions[2]),
    p.Albedo,
    p.Anisotropy,
    p.AmbientRadius };
  if (!averaged)
  {
    error = "the diffusion's cells need the averaged extinction on the GPU";
    return false;
  }
  if (!this->EnsurePrograms(lights, error))
  {
    return false;
  }
  if (this->CellBuffer && key == this->ListedKey)
  {
    return true;
  }
  this->ListedKey.clear();
  if (finest[0] > 2048 || finest[1] > 2048 || finest[2] > 1024)
  {
    error = "the diffusion grid is too large for the GPU solve's lists of cells";
    return false;
  }
  // The levels' textures (kept from the last solve where their sizes stay).
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
    if (!this->Allocate(window, this->LevelFluence(l), levels[l].Dimensions, nullptr, error) ||
      !this->Allocate(window, this->LevelSource(l), levels[l].Dimensions, nullptr, error))
    {
      return false;
    }
  }
  vtkAVSRenderPasses::DiscardErrors();
  window->GetShaderCache()->ReleaseCurrentShader();
  const std::size_t entries = ListBase(levels, levels.size());
  GLint64 largest = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largest);
  if (static_cast<double>(entries) * sizeof(std::uint32_t) > static_cast<double>(largest))
  {
    error = "the diffusion grid (" + std::to_string(finest[0]) + " x " + std::to_string(finest[1]) +
      " x " + std::to_string(finest[2]) + ") is too large for the GPU's shader storage blocks (" +
      std::to_string(largest) + " bytes); lower DiffusionVolumeMaximumDimension";
    return false;
  }
  // (The shaders wrote the lists' headers that are rewritten below.)
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (!this->CellBuffer || this->CellEntries != entries)
  {
    if (!this->CellBuffer)
    {
      glGenBuffers(1, &this->CellBuffer);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->CellBuffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER,
      static_cast<GLsizeiptr>(entries * sizeof(std::uint32_t)),
      nullptr,
      GL_DYNAMIC_DRAW);
    this->CellEntries = entries;
  }
  const GLuint program = this->Programs[ListStage];
  glUseProgram(program);
  this->SetModelUniforms(program, lightDimensions, averaged, p);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->CellBuffer);
  for (std::size_t l = 0; l < levels.size(); ++l)
  {
    const std::array<int, 3>& n = levels[l].Dimensions;
    this->SetLevelUniforms(program, levels, l);
    // The lists start empty: no work groups along x, one along y and z.
    const std::uint32_t empty[8] = { 0, 1, 1, 0, 1, 1, 0, 0 };
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->CellBuffer);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER,
      static_cast<GLintptr>(ListBase(levels, l) * sizeof(std::uint32_t)),
      sizeof(empty),
      empty);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glBindImageTexture(
      0, this->LevelFluence(l)->GetHandle(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    glDispatchCompute(static_cast<GLuint>((n[0] + 7) / 8),
      static_cast<GLuint>((n[1] + 7) / 8),
      static_cast<GLuint>(n[2]));
  }
  glMemoryBarrier(
    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glUseProgram(0);
  averaged->Deactivate();
  if (const GLenum status = glGetError())
  {
    error = "OpenGL error " + std::to_string(status) + " in listing the diffusion's cells";
    return false;
  }
  this->ListedKey = key;
  return true;
}

bool vtkAVSDiffuseVolume::MarkTiles(vtkOpenGLRenderWindow* window,
  const avs::GridGeometry& grid,
  const std::array<int, 3>& lightDimensions,
  const avs::Light& light,
  const avs::ScatteringParameters& p,
  const std::vector<std::uint32_t>& rayTiles,
  vtkAVSTileList& tiles,
  std::string& error)
{
  if (this->ListedKey.empty() || !this->CellBuffer)
  {
    error = "the diffusion's cells are not listed";
    return false;
  }
  const std::vector<avs::GridGeometry> levels = avs::DiffusionLevels(grid);
  // A flag per tile (in AllLightTiles' order), set for the rays' tiles.
  const std::array<int, 3> along = avs::LightTileCounts(lightDimensions);
  const std::size_t count = avs::NumberOfLightTiles(lightDimensions);
  std::vector<std::uint32_t> flags(count, 0u);
  for (const std::uint32_t t : rayTiles)
  {
    flags[avs::LightTileIndex(t, along)] = 1u;
  }
  vtkAVSRenderPasses::DiscardErrors();
  window->GetShaderCache()->ReleaseCurrentShader();
  if (!this->FlagBuffer)
  {
    glGenBuffers(1, &this->FlagBuffer);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->FlagBuffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER,
    static_cast<GLsizeiptr>(count * sizeof(std::uint32_t)),
    flags.data(),
    GL_DYNAMIC_DRAW);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  if (!tiles.Reset(lightDimensions, error))
  {
    return false;
  }
  // The reads of every level's cells, from the light in the local frame.
  GLuint program = this->Programs[MarkStage];
  glUseProgram(program);
  auto location = [&program](const char* name) { return glGetUniformLocation(program, name); };
  this->SetModelUniforms(program, lightDimensions, nullptr, p);
  const bool positional = light.Type == avs::LightType::Positional;
  const avs::Vec3 where = positional
    ? grid.WorldToLocal(light.Position)
    : grid.WorldToLocalDirection(avs::Normalize(light.FocalPoint - light.Position));
  glUniform1i(location("u_markPositional"), positional ? 1 : 0);
  glUniform3f(location("u_markLight"),
    static_cast<float>(where.x),
    static_cast<float>(where.y),
    static_cast<float>(where.z));
  glUniform3i(location("u_tilesAlong"), along[0], along[1], along[2]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->CellBuffer);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, this->FlagBuffer);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, this->CellBuffer);
  for (std::size_t l = 0; l < levels.size(); ++l)
  {
    this->SetLevelUniforms(program, levels, l);
    for (int colour = 0; colour < 2; ++colour)
    {
      glUniform1i(location("u_colour"), colour);
      glDispatchComputeIndirect(
        static_cast<GLintptr>((ListBase(levels, l) + 3 * colour) * sizeof(std::uint32_t)));
    }
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  // The flagged tiles into the list.
  program = this->Programs[CompactStage];
  glUseProgram(program);
  glUniform3i(location("u_tilesAlong"), along[0], along[1], along[2]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, tiles.GetBuffer());
  const std::array<std::uint32_t, 3> groups = vtkAVSTileList::Groups((count + 63) / 64);
  glDispatchCompute(groups[0], groups[1], groups[2]);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  for (unsigned int binding : { 0u, 1u, 2u })
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
  }
  glUseProgram(0);
  if (const GLenum status = glGetError())
  {
    error = "OpenGL error " + std::to_string(status) + " in marking the diffusion's tiles";
    return false;
  }
  return true;
}

void vtkAVSDiffuseVolume::SetModelUniforms(unsigned int program,
  const std::array<int, 3>& lightDimensions,
  vtkTextureObject* averaged,
  const avs::ScatteringParameters& p)
{
  auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
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
  if (averaged)
  {
    averaged->Activate();
    glUniform1i(location("u_averaged"), averaged->GetTextureUnit());
  }
}

void vtkAVSDiffuseVolume::SetLevelUniforms(unsigned int program,
  const std::vector<avs::GridGeometry>& levels,
  std::size_t l)
{
  auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
  const avs::GridGeometry& level = levels[l];
  const std::array<int, 3>& n = level.Dimensions;
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
  glUniform1i(location("u_listBase"), static_cast<GLint>(ListBase(levels, l)));
  glUniform1i(location("u_listCapacity"), static_cast<GLint>(ListCapacity(level)));
}

bool vtkAVSDiffuseVolume::Compute(vtkOpenGLRenderWindow* window,
  const avs::GridGeometry& grid,
  const std::array<int, 3>& lightDimensions,
  const std::vector<std::uint32_t>& tiles,
  vtkTextureObject* averaged,
  vtkTextureObject* lights0,
  vtkTextureObject* lights1,
  const std::vector<avs::Light>& lights,
  const avs::ScatteringParameters& p,
  int averagedVersion,
  std::string& error)
{
  const int n = static_cast<int>(std::min<std::size_t>(lights.size(), 8));
  if (!averaged || (n > 0 && !lights0) || (n > 4 && !lights1))
  {
    error = "the diffusion solve needs the averaged extinction and the light volumes on the GPU";
    return false;
  }
  // The cells that are not vacuum, on every level (kept from the light volumes' tiles).
  if (!this->ListCells(window, grid, lightDimensions, averaged, &lights, p, averagedVersion, error))
  {
    return false;
  }
  const std::vector<avs::GridGeometry> levels = avs::DiffusionLevels(grid);
  // A new packed texture is written everywhere (its texels start undefined), a kept one over
  // the tiles that the rays read.
  const vtkSmartPointer<vtkTextureObject> before = this->Texture; // (held: no other one there)
  if (!this->Allocate(window, this->Texture, lightDimensions, nullptr, error))
  {
    return false;
  }
  const bool fresh = this->Texture != before || this->Dimensions != lightDimensions;
  this->Dimensions = { 0, 0, 0 }; // (set again when the texture is packed)
  if (!this->PackTiles.Set(lightDimensions,
        fresh || tiles.empty() ? avs::AllLightTiles(lightDimensions) : tiles,
        error))
  {
    error = "the diffusion solve: " + error;
    return false;
  }

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
  vtkTextureObject* first = lights0 ? lights0 : averaged;
  vtkTextureObject* second = lights1 ? lights1 : first;
  first->Activate();
  if (second != first)
  {
    second->Activate();
  }
  // What the stages read: the lights (the source's), the model's parameters and the textures.
  for (const int stage : { SourceStage, RelaxStage, PackStage })
  {
    use(this->Programs[stage]);
    this->SetModelUniforms(program, lightDimensions, averaged, p);
    if (stage != SourceStage)
    {
      continue;
    }
    glUniform3fv(location("u_lightPosition"), 8, &position[0][0]);
    glUniform3fv(location("u_lightAxis"), 8, &axis[0][0]);
    glUniform3fv(location("u_lightIrradiance"), 8, &irradiance[0][0]);
    glUniform3fv(location("u_lightAttenuation"), 8, &attenuation[0][0]);
    glUniform1fv(location("u_lightConeCos"), 8, coneCos);
    glUniform1fv(location("u_lightExponent"), 8, exponent);
    glUniform1fv(location("u_sourceWeight"), 8, weight);
    glUniform1i(location("u_lightVolumes0"), first->GetTextureUnit());
    glUniform1i(location("u_lightVolumes1"), second->GetTextureUnit());
  }
  // Coarsest level first; each starts from the coarser one's phi (the source stage's Coarser),
  // with DiffusionCoarseIterations sweeps, the finest with DiffusionIterations, over the lists
  // of its cells that are not vacuum (a half-sweep per colour).
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->CellBuffer);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, this->CellBuffer);
  for (std::size_t l = levels.size(); l-- > 0;)
  {
    vtkTextureObject* phi = this->LevelFluence(l);
    vtkTextureObject* q = this->LevelSource(l);
    vtkTextureObject* coarser = l + 1 < levels.size() ? this->LevelFluence(l + 1).Get() : phi;
    glBindImageTexture(0, phi->GetHandle(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(1, q->GetHandle(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(2, coarser->GetHandle(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    const std::size_t base = ListBase(levels, l);
    auto overList = [&](int colour)
    {
      glUniform1i(location("u_colour"), colour);
      glDispatchComputeIndirect(static_cast<GLintptr>((base + 3 * colour) * sizeof(std::uint32_t)));
      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    };
    use(this->Programs[SourceStage]);
    this->SetLevelUniforms(program, levels, l);
    overList(0);
    overList(1);
    use(this->Programs[RelaxStage]);
    this->SetLevelUniforms(program, levels, l);
    const int sweeps = l == 0 ? p.DiffusionIterations : p.DiffusionCoarseIterations;
    for (int it = 0; it < sweeps; ++it)
    {
      overList(0);
      overList(1);
    }
  }
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  // phi onto the light grid, with the averaged extinction, for the ray caster's one fetch, over
  // the tiles that the rays read (a work group each).
  {
    const std::array<int, 3>& m = grid.Dimensions;
    use(this->Programs[PackStage]);
    glUniform3i(
      location("u_dimensions"), lightDimensions[0], lightDimensions[1], lightDimensions[2]);
    glUniform3i(location("u_coarserDimensions"), m[0], m[1], m[2]);
    glBindImageTexture(2, this->Fluence->GetHandle(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(3, this->Texture->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    this->PackTiles.Dispatch(1);
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
  this->Dimensions = lightDimensions;
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
  for (unsigned int* buffer : { &this->CellBuffer, &this->FlagBuffer })
  {
    if (*buffer && window)
    {
      glDeleteBuffers(1, buffer);
    }
    *buffer = 0;
  }
  this->CellEntries = 0;
  this->ListedKey.clear();
  this->PackTiles.ReleaseGraphicsResources(window != nullptr);
  this->ProgramDefines.clear();
  this->Dimensions = { 0, 0, 0 };
}
