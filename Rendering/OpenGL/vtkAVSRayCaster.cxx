#include "vtkAVSRayCaster.h"

#include "DiffuseFluence.h"
#include "LightTiles.h"

#include "vtkAVSFrameUniforms.h"
#include "vtkAVSRenderPasses.h"
#include "vtkAVSShaderAssembly.h"
#include "vtkAVSTextureMemory.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolumeMapper.h"

#include <algorithm>
#include <cmath>

vtkAVSRayCaster::vtkAVSRayCaster()
{
  // One GPU memory budget for all of the volume's 3D textures.
  this->Textures.OtherTextures = [this]() { return this->Diffuse.GetTextures(); };
  this->Diffuse.OtherTextures = [this]() { return this->Textures.VolumeTextures(); };
}

vtkAVSRayCaster::~vtkAVSRayCaster()
{
  this->ReleaseGraphicsResources(this->Window);
}

void vtkAVSRayCaster::SetWindow(vtkOpenGLRenderWindow* window)
{
  if (window != this->Window)
  {
    this->ReleaseGraphicsResources(this->Window);
    this->Window = window;
    this->Textures.SetWindow(window);
  }
}

void vtkAVSRayCaster::ReleaseGraphicsResources(vtkWindow* window)
{
  // The deletes below go to the current context: make it the window's (a mapper destroyed or
  // moved while another window's context is current deleted that context's objects of the
  // same names; found by the soak), and restore the previous one after.
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (context)
  {
    context->PushContext();
  }
  this->Textures.ReleaseGraphicsResources(window);
  this->Diffuse.ReleaseGraphicsResources(window); // the extended model
  this->Depth.ReleaseGraphicsResources(window);
  this->ImageSampler.ReleaseGraphicsResources(window);
  this->Refinement.ReleaseGraphicsResources(window);
  if (this->Quad && window)
  {
    this->Quad->ReleaseGraphicsResources(window);
  }
  this->Quad.reset();
  this->QuadMode = -1;
  this->QuadDefines.clear();
  // Without a window (it was deleted, and its context with it) the program names are only
  // forgotten: they must not be used in the next context.
  this->LightVolumePass.ReleaseGraphicsResources(context != nullptr);
  this->OcclusionPass.ReleaseGraphicsResources(context != nullptr);
  this->AveragedExtinctionPass.ReleaseGraphicsResources(context != nullptr);
  this->ComputeSupport = -1; // asked again in the next context
  this->ReportedMemory = -1.0;
  if (window == this->Window)
  {
    this->Window = nullptr;
  }
  if (context)
  {
    context->PopContext();
  }
}

int vtkAVSRayCaster::MaximumTextureSize3D() const
{
  return this->Textures.MaximumTextureSize3D();
}

// The uploads: vtkAVSVolumeTextures.
bool vtkAVSRayCaster::UploadScalars(const avs::VolumeScene& scene,
  int scalarType,
  const vtkAVSVolumeTextures::ScalarSource& source,
  const std::array<int, 3>& partitions,
  const std::array<int, 3>& lookBack,
  std::string& error)
{
  return this->Textures.UploadScalars(scene, scalarType, source, partitions, lookBack, error);
}

std::array<int, 3> vtkAVSRayCaster::LookBackVoxels(double radius,
  double sampleDistance,
  const avs::Vec3& spacing)
{
  // The look-back reaches r + one step along the ray, so at most that along each grid axis.
  const double h[3] = { spacing.x, spacing.y, spacing.z };
  std::array<int, 3> voxels{ 0, 0, 0 };
  for (int a = 0; a < 3; ++a)
  {
    voxels[a] = h[a] > 0.0 ? static_cast<int>(std::ceil((radius + sampleDistance) / h[a])) : 0;
  }
  return voxels;
}

int vtkAVSRayCaster::GetNumberOfBricks() const
{
  const vtkAVSVolumeTextures& tx = this->Textures;
  return tx.Bricks.IsSplit() ? tx.Bricks.GetNumberOfBricks() : (tx.Scalars ? 1 : 0);
}

double vtkAVSRayCaster::ReportedGPUMemoryBytes()
{
  if (this->ReportedMemory >= 0.0)
  {
    return this->ReportedMemory;
  }
  this->ReportedMemory = 0.0;
  if (!this->Window)
  {
    return 0.0;
  }
  this->ReportedMemory = vtkAVSTextureMemory::ReportedBytes();
  return this->ReportedMemory;
}

bool vtkAVSRayCaster::UploadClassification(const avs::VolumeScene& scene, std::string& error)
{
  return this->Textures.UploadClassification(scene, error);
}

bool vtkAVSRayCaster::UploadSurfaces(const avs::VolumeScene& scene,
  bool active,
  const vtkAVSVolumeTextures::ScalarSource& source,
  std::string& error)
{
  this->Textures.SetWindow(this->Window);
  return this->Textures.UploadSurfaces(scene, active, source, error);
}

bool vtkAVSRayCaster::UploadAveraged(const avs::Grid& averaged, std::string& error)
{
  return this->Textures.UploadAveraged(averaged, error);
}

bool vtkAVSRayCaster::UploadLightVolumes(const std::vector<avs::Grid>& lights, std::string& error)
{
  return this->Textures.UploadLightVolumes(lights, error);
}

bool vtkAVSRayCaster::UploadOcclusion(const avs::Grid& occlusion, std::string& error)
{
  return this->Textures.UploadOcclusion(occlusion, error);
}

bool vtkAVSRayCaster::UploadTableSlice(const avs::ScatteringSlice& slice, std::string& error)
{
  return this->Textures.UploadTableSlice(slice, error);
}

bool vtkAVSRayCaster::EnsureProgram(avs::RenderMode mode, const std::string& defines)
{
  if (this->Quad && this->QuadMode == static_cast<int>(mode) && this->QuadDefines == defines)
  {
    return true;
  }
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(this->Window);
    this->Quad.reset();
  }
  const std::string fs = vtkAVSShaderAssembly::RayCastFragmentShader(mode, defines);
  this->Quad = std::make_unique<vtkOpenGLQuadHelper>(this->Window, nullptr, fs.c_str(), "");
  if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
  {
    this->Quad.reset();
    return false;
  }
  this->QuadMode = static_cast<int>(mode);
  this->QuadDefines = defines;
  return true;
}

bool vtkAVSRayCaster::SupportsComputeShaders()
{
  if (this->ComputeSupport >= 0)
  {
    return this->ComputeSupport == 1;
  }
  this->ComputeSupport = 0;
  if (!this->Window)
  {
    return false;
  }
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if ((major < 4 || (major == 4 && minor < 3)) || !glDispatchCompute || !glBindImageTexture)
  {
    return false;
  }
  const bool lightVolume =
    this->LightVolumePass.Build(MaximumTauNodes, this->Textures.IsSoftwareRenderer());
  const bool occlusion = this->OcclusionPass.Build();
  // The averaged-extinction program depends on the classification; it is built for the
  // current one when first needed (ComputeAveragedExtinction). Here: that it compiles.
  const bool averaged = this->AveragedExtinctionPass.Build(vtkAVSClassification::Layout()) != 0;
  this->ComputeSupport = lightVolume && occlusion && averaged ? 1 : 0;
  if (!this->ComputeSupport)
  {
    vtkGenericWarningMacro("A compute shader did not build (see above): the precomputation runs "
                           "on the CPU.");
  }
  return this->ComputeSupport == 1;
}

bool vtkAVSRayCaster::ComputeAveragedExtinction(const std::array<int, 3>& dimensions,
  const std::array<int, 3>& lightDimensions,
  const std::array<int, 3>& halfWidths,
  const avs::ClipRegion& clip,
  std::string& error)
{
  if (!this->SupportsComputeShaders() || !this->Textures.Scalars ||
    !this->Textures.Classification.IsUploaded())
  {
    error = "no compute shaders, scalars or transfer function";
    return false;
  }
  return this->AveragedExtinctionPass.Run(
    this->Textures, dimensions, lightDimensions, halfWidths, clip, error);
}

bool vtkAVSRayCaster::ComputeOcclusion(const avs::GridGeometry& geometry,
  const std::array<int, 3>& dimensions,
  double radius,
  int directions,
  const avs::ClipRegion& clip,
  std::string& error)
{
  vtkAVSVolumeTextures& tx = this->Textures;
  if (!this->SupportsComputeShaders() || directions > 256 || !tx.Scalars ||
    !tx.Classification.IsUploaded())
  {
    error = "no compute shaders, scalars or transfer function, or more than 256 directions";
    return false;
  }
  // sigma_t on the data grid, classified on the GPU, for the pass alone.
  vtkSmartPointer<vtkTextureObject> sigma;
  if (!tx.UploadGrid(sigma, geometry.Dimensions, 1, nullptr, error))
  {
    return false;
  }
  const bool done =
    this->AveragedExtinctionPass.Classify(tx, geometry.Dimensions, clip, sigma, error) &&
    this->OcclusionPass.Run(tx, geometry, sigma, dimensions, radius, directions, error);
  tx.NoteTemporary(sigma); // beside the occlusion volume the pass allocated
  sigma->ReleaseGraphicsResources(this->Window);
  return done;
}

bool vtkAVSRayCaster::ComputeLightVolume(int index,
  const avs::GridGeometry& lightGrid,
  const avs::Light& light,
  double radius,
  avs::TubeLaw law,
  std::string& error)
{
  const std::vector<float>& logGain = this->Textures.LogGain;
  if (!this->SupportsComputeShaders() || !this->Textures.AveragedExtinction || logGain.size() < 2)
  {
    error = "no compute shaders, averaged extinction or table slice";
    return false;
  }
  if (logGain.size() > static_cast<std::size_t>(MaximumTauNodes))
  {
    error = "the scattering table has more tau nodes than the GPU light-volume pass takes (" +
      std::to_string(MaximumTauNodes) + ")";
    return false;
  }
  return this->LightVolumePass.Run(this->Textures, index, lightGrid, light, radius, law, error);
}

bool vtkAVSRayCaster::UpdateLightTiles(const avs::GridGeometry& lightGrid,
  const avs::Light& light,
  const avs::ScatteringParameters& resolved,
  bool diffusion,
  bool skipEmpty,
  int averagedVersion,
  std::string& error)
{
  const std::array<int, 3>& l = lightGrid.Dimensions;
  std::vector<std::uint32_t> tiles = this->RayTiles(lightGrid, skipEmpty);
  if (!diffusion || tiles.size() == avs::NumberOfLightTiles(l))
  {
    return this->LightVolumePass.SetTiles(l, tiles, error);
  }
  // The diffusion's reads, from its cells that are not vacuum, on the GPU.
  const avs::GridGeometry grid =
    avs::DiffusionGeometry(lightGrid, resolved.DiffusionVolumeMaximumDimension);
  return this->Diffuse.ListCells(this->Textures.Window,
           grid,
           l,
           this->Textures.AveragedExtinction,
           nullptr,
           resolved,
           averagedVersion,
           error) &&
    this->Diffuse.MarkTiles(this->Textures.Window,
      grid,
      l,
      light,
      resolved,
      tiles,
      this->LightVolumePass.GetTiles(),
      error);
}

std::vector<std::uint32_t> vtkAVSRayCaster::RayTiles(const avs::GridGeometry& lightGrid,
  bool skipEmpty) const
{
  const avs::ValueRangeGrid& ranges = this->Textures.ValueRanges;
  const std::array<int, 3>& d = ranges.Dimensions();
  const std::array<int, 3>& l = lightGrid.Dimensions;
  if (!skipEmpty || ranges.Empty() ||
    this->Textures.MajorantValues.size() != ranges.NumberOfCells() || d[0] < 2 || d[1] < 2 ||
    d[2] < 2)
  {
    return avs::AllLightTiles(l);
  }
  return avs::LightGridTiles(
    this->Textures.MajorantValues, ranges.Cells(), ranges.CellSize(), d, l, avs::RayReach(d, l));
}

bool vtkAVSRayCaster::PackAveraged(int lights, std::string& error)
{
  vtkAVSVolumeTextures& tx = this->Textures;
  const int texture = lights / 4;
  if (lights < 1 || lights % 4 == 0 || lights > MaximumNumberOfLights ||
    !this->SupportsComputeShaders() || tx.HasAveragedIn(lights) || !tx.LightVolumes[texture] ||
    !tx.IsOnLightGrid(tx.AveragedExtinction))
  {
    return true; // nothing to copy, or nowhere to copy it: the rays read its own texture
  }
  return this->LightVolumePass.CopyAveraged(tx, lights, error);
}

bool vtkAVSRayCaster::PackFluence(const std::vector<avs::Light>& lights, std::string& error)
{
  vtkAVSVolumeTextures& tx = this->Textures;
  const int n = static_cast<int>(lights.size());
  vtkTextureObject* fluence = this->Diffuse.GetTexture();
  avs::Vec3 colour;
  // The slot after the averaged extinction's copy, in the same texture (1, 2, 5 or 6 lights).
  if (n < 1 || n % 4 == 0 || n % 4 == 3 || n > MaximumNumberOfLights ||
    !this->SupportsComputeShaders() || !tx.HasAveragedIn(n) || !tx.IsOnLightGrid(fluence) ||
    tx.HasFluenceIn(n + 1, this->Diffuse.GetWrites()) || !avs::CommonColour(lights, colour))
  {
    return true; // current, or nowhere to copy it: the rays read the fluence's texture
  }
  return this->LightVolumePass.CopyFluence(
    tx, n + 1, fluence, this->Diffuse.GetWrites(), colour, error);
}

bool vtkAVSRayCaster::Render(vtkRenderer* renderer, const Frame& frame, std::string& error)
{
  vtkOpenGLRenderWindow* window = this->Window;
  vtkAVSVolumeTextures& tx = this->Textures;
  const bool bricked = tx.Bricks.IsSplit();
  if (!window || !(tx.Scalars || bricked) || !tx.Classification.IsUploaded())
  {
    error = "nothing uploaded";
    return false;
  }
  const vtkAVSClassification::Layout& layout = tx.Classification.GetLayout();
  if (layout.ScalarChannels() != tx.ScalarLayout.ScalarChannels())
  {
    error = "the scalars and the classification do not match";
    return false;
  }
  const bool blend = frame.Mode == avs::RenderMode::EmissionAbsorption;
  // Ambient scattering reads the averaged extinction from the light textures where PackAveraged
  // left a copy in the channel after the last light's; the extended model from the diffuse
  // fluence's texture.
  const int lightCount =
    static_cast<int>(std::min<std::size_t>(frame.Lights.size(), MaximumNumberOfLights));
  const bool extended = frame.Mode == avs::RenderMode::AmbientScattering &&
    frame.Parameters.Model == avs::ScatteringModel::Extended;
  // With lights of one colour, the extended model's fluence as one number in the channel after
  // the averaged extinction's (PackFluence), both read with the lights.
  avs::Vec3 fluenceColour;
  const bool fluencePacked = extended && tx.HasAveragedIn(lightCount) &&
    tx.HasFluenceIn(lightCount + 1, this->Diffuse.GetWrites()) &&
    avs::CommonColour(frame.Lights, fluenceColour);
  const bool packed = frame.Mode == avs::RenderMode::AmbientScattering &&
    (!extended || fluencePacked) && tx.HasAveragedIn(lightCount);
  // Empty-space skipping: not for the blend modes other than composite (they read every
  // sample's scalar) nor for ambient scattering's explicit look-ahead (a sample adds the light
  // of one ahead of it).
  const bool skip = frame.SkipEmptySpace && tx.Occupancy &&
    !(blend && frame.Blend.Mode != vtkVolumeMapper::COMPOSITE_BLEND) &&
    !(frame.Mode == avs::RenderMode::AmbientScattering &&
      vtkAVSShaderAssembly::RingSize(frame.Parameters) == 0);
  // Surfaces whose texture holds the scalars too: each sample's fetch brings its gradient
  // (avs_surface.glsl), where the look-ahead is the ring's (the explicit one reads samples ahead
  // from the scalars).
  // (The layout checked again: the texture was packed for the scalars' layout at its upload.)
  const bool packedSurfaces = frame.Mode == avs::RenderMode::AmbientScattering &&
    frame.Parameters.Surface.Active() && tx.SurfacesPacked && tx.Surfaces.IsUploaded() &&
    !bricked && vtkAVSShaderAssembly::RingSize(frame.Parameters) != 0 && layout.ScalarAlone();
  this->LastSkipped = false;
  if (!this->EnsureProgram(frame.Mode,
        vtkAVSShaderAssembly::RayCastDefines(frame.Mode,
          frame.Parameters,
          frame.Lights,
          static_cast<int>(tx.TableSize[1]),
          layout,
          packed ? lightCount : -1,
          fluencePacked ? lightCount + 1 : -1,
          frame.LightGroup) +
          vtkAVSShaderOptions::ClipDefines(frame.Clip) +
          (blend ? vtkAVSShaderOptions::BlendDefines(frame.Blend) : std::string()) +
          (bricked ? "#define AVS_BRICKED\n" : "") + (skip ? "#define AVS_SKIP\n" : "") +
          (packedSurfaces ? "#define AVS_SURFACE_PACKED\n" : "")))
  {
    error = "the ray-casting shader did not compile or link (see the log above)";
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  vtkAVSRenderPasses::DiscardErrors(); // what others left; the check at the end is of this pass
  // The current viewport: the renderer's, or a render pass's in its own framebuffer.
  const vtkAVSRenderPasses::Region region = vtkAVSRenderPasses::Locate(window, renderer);
  const int x = region.Draw[0], y = region.Draw[1], width = region.Draw[2], height = region.Draw[3];

  // Copy the depth of what was drawn before, to end rays at opaque geometry.
  this->Depth.Capture(window, region.ReadOrigin[0], region.ReadOrigin[1], width, height);
  vtkTextureObject* depth = this->Depth.GetTexture();
  depth->Activate();

  window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  vtkShaderProgram* program = this->Quad->Program;

  // The camera, the volume's placement, the lights and the parameters (vtkAVSFrameUniforms).
  vtkAVSFrameUniforms::SetGeometry(program, renderer, width, height, frame);
  vtkAVSFrameUniforms::SetLights(program, frame.Lights);
  vtkAVSFrameUniforms::SetParameters(program, frame);
  vtkAVSShaderOptions::SetClipUniforms(program, frame.Clip);
  if (blend)
  {
    vtkAVSShaderOptions::SetBlendUniforms(program, frame.Blend);
  }
  program->SetUniformi("u_depth", depth->GetTextureUnit());
  vtkAVSFrameUniforms::SetDisplay(program, frame.Display);
  // The volume and its classification (avs_classify.glsl), with the interpolation type's filter.
  if (!bricked)
  {
    vtkAVSVolumeTextures::SetVolumeFilter(tx.Scalars, layout.Nearest);
    tx.Scalars->Activate();
    program->SetUniformi("u_scalars", tx.Scalars->GetTextureUnit());
  }
  tx.Classification.Bind(static_cast<unsigned int>(program->GetHandle()));
  tx.Surfaces.Bind(static_cast<unsigned int>(program->GetHandle()), layout.Nearest);
  if (packedSurfaces)
  {
    // A packed scalar a * scale + shift, as the scalars' texel u of u * Scale + Shift.
    const double scale = tx.ScalarFormat.Scale != 0.0f ? tx.ScalarFormat.Scale : 1.0f;
    program->SetUniformf("u_packedScale", static_cast<float>(tx.SurfacesPackedScale / scale));
    program->SetUniformf("u_packedShift",
      static_cast<float>((tx.SurfacesPackedShift - tx.ScalarFormat.Shift) / scale));
  }
  if (skip)
  {
    tx.Occupancy->Activate();
    program->SetUniformi("u_occupancy", tx.Occupancy->GetTextureUnit());
    const std::array<int, 3>& cells = tx.ValueRanges.Cells();
    const float count[3] = {
      static_cast<float>(cells[0]), static_cast<float>(cells[1]), static_cast<float>(cells[2])
    };
    program->SetUniform3f("u_occupancyCells", count);
    program->SetUniformf("u_cellSize", static_cast<float>(tx.ValueRanges.CellSize()));
  }
  // The pass: one quad, or one per brick back to front (vtkAVSBricks), each composited over
  // what the bricks behind it left, in the image sampler's half-float target (at every image
  // sample distance: the framebuffer's 8 bits would round each brick's composite).
  const std::vector<int> order = bricked
    ? tx.Bricks.BackToFront(vtkAVSFrameUniforms::EyeInIndexFrame(renderer, frame))
    : std::vector<int>();
  auto drawPass = [&]
  {
    if (!bricked)
    {
      this->Quad->Render();
      return;
    }
    for (int b : order)
    {
      vtkTextureObject* texture = tx.BrickTextures[static_cast<std::size_t>(b)];
      vtkAVSVolumeTextures::SetVolumeFilter(texture, layout.Nearest);
      texture->Activate();
      program->SetUniformi("u_scalars", texture->GetTextureUnit());
      vtkAVSFrameUniforms::SetBrick(program, tx.Bricks.GetBricks()[static_cast<std::size_t>(b)]);
      tx.Classification.BindBrick(static_cast<unsigned int>(program->GetHandle()), b);
      tx.Surfaces.BindBrick(static_cast<unsigned int>(program->GetHandle()), b, layout.Nearest);
      this->Quad->Render();
      texture->Deactivate();
    }
  };

  if (frame.Mode == avs::RenderMode::AmbientOcclusion)
  {
    if (!tx.Occlusion)
    {
      error = "no occlusion volume uploaded";
      return false;
    }
    tx.Occlusion->Activate();
    program->SetUniformi("u_occlusion", tx.Occlusion->GetTextureUnit());
    // Data index -> occlusion texture coordinate: index * scale + offset.
    float scale[3], offset[3];
    for (int a = 0; a < 3; ++a)
    {
      const double l = frame.OcclusionDimensions[a], n = frame.Dimensions[a];
      scale[a] = static_cast<float>(n > 1 ? (l - 1) / ((n - 1) * l) : 0.0);
      offset[a] = static_cast<float>(0.5 / l);
    }
    program->SetUniform3f("u_occlusionScale", scale);
    program->SetUniform3f("u_occlusionOffset", offset);
  }
  else if (frame.Mode == avs::RenderMode::AmbientScattering)
  {
    const int n =
      static_cast<int>(std::min<std::size_t>(frame.Lights.size(), MaximumNumberOfLights));
    const int textures = vtkAVSVolumeTextures::LightTexturesFor(n);
    auto dimensionsOf = [](vtkTextureObject* t) -> std::array<int, 3>
    {
      return { static_cast<int>(t->GetWidth()),
        static_cast<int>(t->GetHeight()),
        static_cast<int>(t->GetDepth()) };
    };
    if (!tx.Table || !tx.AveragedExtinction ||
      dimensionsOf(tx.AveragedExtinction) != frame.LightVolumeDimensions ||
      (textures > 0 && frame.LightVolumeDimensions != tx.LightTextureDimensions) ||
      !std::all_of(tx.LightVolumes,
        tx.LightVolumes + textures,
        [](const vtkSmartPointer<vtkTextureObject>& t) { return t != nullptr; }))
    {
      error = "the scattering volumes are not uploaded";
      return false;
    }
    if (!packed && !extended)
    {
      tx.AveragedExtinction->Activate();
      program->SetUniformi("u_averagedExtinction", tx.AveragedExtinction->GetTextureUnit());
    }
    const char* names[vtkAVSVolumeTextures::NumberOfLightTextures] = { "u_lightVolumes0",
      "u_lightVolumes1" };
    for (int t = 0; t < textures; ++t)
    {
      tx.LightVolumes[t]->Activate();
      program->SetUniformi(names[t], tx.LightVolumes[t]->GetTextureUnit());
    }
    const float lvd[3] = { static_cast<float>(frame.LightVolumeDimensions[0]),
      static_cast<float>(frame.LightVolumeDimensions[1]),
      static_cast<float>(frame.LightVolumeDimensions[2]) };
    program->SetUniform3f("u_lightVolumeDimensions", lvd);
    const float whole[3] = { static_cast<float>(frame.WholeDimensions[0]),
      static_cast<float>(frame.WholeDimensions[1]),
      static_cast<float>(frame.WholeDimensions[2]) };
    program->SetUniform3f("u_wholeDimensions", whole);
    const float offset[3] = { static_cast<float>(frame.PieceOffset[0]),
      static_cast<float>(frame.PieceOffset[1]),
      static_cast<float>(frame.PieceOffset[2]) };
    program->SetUniform3f("u_pieceOffset", offset);
    tx.Table->Activate();
    program->SetUniformi("u_table", tx.Table->GetTextureUnit());
    program->SetUniform2f("u_tableSize", tx.TableSize);
    program->SetUniformf("u_tableTauMaximum", tx.TableTauMaximum);
    // The extended model (vtkAVSDiffuseVolume).
    if (extended)
    {
      if (!this->Diffuse.IsReady())
      {
        error = "the diffuse fluence is not uploaded";
        return false;
      }
      this->Diffuse.Bind(program, frame.Parameters, fluencePacked ? &fluenceColour : nullptr);
    }
  }

  // Ambient scattering's path-traced refinement: its buffers restart when the key or the size
  // changes, at every frame, so that a reduced frame after a change adds nothing to old samples.
  this->LastRefined = false;
  bool refine = frame.Refinement.Enabled && frame.Mode == avs::RenderMode::AmbientScattering &&
    !bricked && !frame.PeelingFront;
  if (refine &&
    !this->Refinement.Begin(
      window, width, height, frame.Refinement.Key, frame.Refinement.Geometry, error))
  {
    // (Float buffers of the viewport's size refused: the frame is drawn unrefined; one
    // warning until a refinement starts again.)
    if (!this->RefinementRefused)
    {
      vtkGenericWarningMacro("Path-traced refinement is not done: " << error << ".");
    }
    this->RefinementRefused = true;
    error.clear();
    refine = false;
  }
  else if (refine)
  {
    this->RefinementRefused = false;
  }
  if (!refine)
  {
    this->Refinement.Reset(); // the samples were of another frame
  }

  // The render passes attached to the volume set what they need (vtkSSAOPass: the colour
  // target alone).
  vtkAVSRenderPasses::SetShaderParameters(frame.Prop, frame.Mapper, program);

  // Composite the premultiplied result over the framebuffer; leave depth untouched.
  {
    vtkAVSRenderPasses::ScopedCompositing compositing(state);
    vtkOpenGLState::ScopedglViewport viewportGuard(state);
    vtkAVSRenderPasses::ScopedDrawBuffer target(state, frame.PeelingFront ? 1 : 0);
    // At an image sample distance other than 1 (and for a split volume) the pass goes through an
    // offscreen target and is composited from it; otherwise, or when that target cannot be made,
    // straight into the viewport. A still frame of the path-traced refinement shows the refined
    // picture instead.
    vtkOpenGLShaderCache* cache = window->GetShaderCache();
    if (refine && this->Refine(renderer, frame, program, drawPass, x, y, width, height, error))
    {
      this->LastPassSize = { width, height };
      this->LastRefined = true;
    }
    else if (!error.empty())
    {
      return false;
    }
    else if (this->ImageSampler.Draw(
               window,
               x,
               y,
               width,
               height,
               frame.ImageSampleDistance,
               [&]
               {
                 cache->ReadyShaderProgram(program);
                 program->SetUniformi("u_displayInRay", 0); // the compositing applies it
                 drawPass();
               },
               frame.Display,
               bricked))
    {
      this->LastPassSize = { this->ImageSampler.GetTargetWidth(),
        this->ImageSampler.GetTargetHeight() };
    }
    else
    {
      // Straight into the viewport: the ray maps its own radiance. (A split volume whose target
      // could not be made comes here too: then each brick's pass is mapped alone.)
      program->SetUniformi("u_displayInRay", 1);
      state->vtkglViewport(x, y, width, height);
      drawPass();
      this->LastPassSize = { width, height };
    }
  }

  tx.Classification.Unbind();
  tx.Surfaces.Unbind();
  this->Diffuse.Unbind(); // the extended model
  for (vtkTextureObject* t : { this->Depth.GetTexture(),
         tx.Scalars.Get(),
         tx.Occlusion.Get(),
         tx.Occupancy.Get(),
         tx.AveragedExtinction.Get(),
         tx.LightVolumes[0].Get(),
         tx.LightVolumes[1].Get(),
         tx.Table.Get() })
  {
    if (t && t->GetTextureUnit() >= 0)
    {
      t->Deactivate();
    }
  }
  if (const GLenum status = glGetError())
  {
    error = "OpenGL error " + std::to_string(status) + " while drawing the volume";
    return false;
  }
  this->LastSkipped = skip;
  return true;
}

// The extended model's GPU diffusion solve (vtkAVSDiffuseVolume) reads these.
vtkTextureObject* vtkAVSRayCaster::GetAveragedExtinctionTexture() const
{
  return this->Textures.AveragedExtinction;
}

double vtkAVSRayCaster::VolumeTextureBytes() const
{
  return this->Textures.HeldBytes() + this->Diffuse.HeldBytes();
}

double vtkAVSRayCaster::PeakVolumeTextureBytes() const
{
  // The extended model's textures stay from one solve to the next, through the rebuilds whose
  // peaks the volume textures note.
  return this->Textures.GetPeakBytes() + this->Diffuse.HeldBytes();
}

vtkTextureObject* vtkAVSRayCaster::GetLightVolumeTexture(int t) const
{
  return t >= 0 && t < vtkAVSVolumeTextures::NumberOfLightTextures
    ? this->Textures.LightVolumes[t].Get()
    : nullptr;
}
