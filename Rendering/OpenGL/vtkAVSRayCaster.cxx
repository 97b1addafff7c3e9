#include "vtkAVSRayCaster.h"

#include "vtkAVSRenderPasses.h"
#include "vtkAVSShaders.h"
#include "vtkAVSTextureMemory.h"

#include "AmbientOcclusion.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

namespace
{
// Splits an effect file into its declarations, its per-ray set-up (optional) and its
// per-sample code, in that order.
void SplitEffect(const std::string& text, std::string& dec, std::string& init, std::string& sample)
{
  const std::string initMarker = "//AVS::Effect::Init";
  const std::string sampleMarker = "//AVS::Effect::Sample";
  const std::size_t sampleAt = std::min(text.find(sampleMarker), text.size());
  const std::size_t initAt = std::min(text.find(initMarker), sampleAt);
  dec = text.substr(0, initAt);
  init = initAt < sampleAt
    ? text.substr(initAt + initMarker.size(), sampleAt - initAt - initMarker.size())
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

// Compile-time choices of the ray-casting program for a frame (see avs_lights.glsl and the
// effect files): the number of lights and which are positional or spots, AO's direct light,
// and for ambient scattering the ring buffer's size (or the explicit look-ahead), the light
// textures to fetch, emission and the per-ray table columns of directional lights. One program
// per combination.
std::string ProgramDefines(const vtkAVSRayCaster::Frame& frame,
  int tauNodes,
  const vtkAVSClassification::Layout& layout,
  int averagedChannel)
{
  // The classification's choices (avs_classify.glsl); ambient scattering reads the volume's
  // channels and the averaged extinction from one texture where they fit.
  std::string defines = layout.Defines();
  if (frame.Mode == avs::RenderMode::AmbientScattering)
  {
    defines += averagedChannel >= 0 ? "#define AVS_VOLUME_TEXTURE u_scalarsAveraged\n"
                                      "#define AVS_AVERAGED_CHANNEL " +
        std::to_string(averagedChannel) + "\n"
                                    : std::string("#define AVS_AVERAGED_TEXTURE\n");
  }
  if (frame.Mode == avs::RenderMode::EmissionAbsorption)
  {
    return defines;
  }
  const avs::ScatteringParameters& p = frame.Parameters;
  defines += "#define AVS_NUMBER_OF_LIGHTS " + std::to_string(frame.Lights.size()) + "\n";
  int positional = 0;
  for (std::size_t j = 0; j < frame.Lights.size(); ++j)
  {
    positional |= frame.Lights[j].Type == avs::LightType::Positional ? 1 << j : 0;
  }
  defines += "#define AVS_POSITIONAL_LIGHTS " + std::to_string(positional) + "\n";
  if (std::any_of(
        frame.Lights.begin(), frame.Lights.end(), [](const avs::Light& l) { return l.IsSpot(); }))
  {
    defines += "#define AVS_SPOT_LIGHTS\n";
  }
  if (frame.Mode == avs::RenderMode::AmbientOcclusion)
  {
    if (p.DirectLightWeight > 0.0 && !frame.Lights.empty())
    {
      defines += "#define AVS_DIRECT_LIGHT\n";
    }
    return defines;
  }
  // A ray of two or more steps has dt >= sample distance / 2, so the look-ahead k = floor(r /
  // dt), which needs k + 2 entries, is at most 2 r / sample distance; a ray of one step adds no
  // in-scattered light.
  const double most = 2.0 * p.AmbientRadius / p.SampleDistance + 2.0;
  int ring = 16;
  while (ring < most && ring <= vtkAVSRayCaster::MaximumRingSize)
  {
    ring *= 2;
  }
  defines += ring > vtkAVSRayCaster::MaximumRingSize
    ? "#define AVS_LOOKAHEAD_EXPLICIT\n"
    : "#define AVS_RING " + std::to_string(ring) + "\n";
  // The extended model: one more fetch per sample, of the diffuse fluence (vtkAVSDiffuseVolume).
  if (p.Model == avs::ScatteringModel::Extended)
  {
    defines += "#define AVS_DIFFUSE\n";
  }
  // Light-volume textures to fetch: lights 0-3, 4-7.
  const int n = static_cast<int>(frame.Lights.size());
  defines +=
    "#define AVS_LIGHT_TEXTURES " + std::to_string(vtkAVSRayCaster::LightTexturesFor(n)) + "\n";
  if (p.EmissionWeight > 0.0 && p.Albedo < 1.0)
  {
    defines += "#define AVS_EMISSION\n";
  }
  // Directional lights read A from a per-ray column of the table (see avs_as_effect.glsl) when
  // the table's tau axis is short enough to keep one column per light.
  if (positional != (1 << n) - 1 && tauNodes >= 2 && tauNodes <= vtkAVSRayCaster::MaximumTauNodes)
  {
    defines += "#define AVS_TABLE_COLUMN " + std::to_string(tauNodes) + "\n";
  }
  return defines;
}

void ConfigureSampling(vtkTextureObject* t)
{
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->SetWrapR(vtkTextureObject::ClampToEdge);
  t->SetMinificationFilter(vtkTextureObject::Linear);
  t->SetMagnificationFilter(vtkTextureObject::Linear);
}
} // namespace

vtkAVSRayCaster::vtkAVSRayCaster() = default;

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
    this->Classification.SetWindow(window);
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
  this->Classification.ReleaseGraphicsResources(window);
  for (vtkTextureObject* t : { this->Scalars.Get(),
         this->ScalarsAveraged.Get(),
         this->AveragedExtinction.Get(),
         this->Occlusion.Get(),
         this->Table.Get(),
         this->Depth.Get(),
         this->LightVolumes[0].Get(),
         this->LightVolumes[1].Get(),
         this->Scratch[0].Get(),
         this->Scratch[1].Get(),
         this->Scratch[2].Get() })
  {
    if (t && window)
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  this->Scalars = this->ScalarsAveraged = this->AveragedExtinction = this->Occlusion = this->Table =
    this->Depth = nullptr;
  for (auto& t : this->LightVolumes)
  {
    t = nullptr;
  }
  for (auto& t : this->Scratch)
  {
    t = nullptr;
  }
  this->LightTextureDimensions = { 0, 0, 0 };
  this->Diffuse.ReleaseGraphicsResources(window); // the extended model
  // The depth-copy framebuffer belongs to the context too (kept, it would bind a deleted
  // window's context in the next one).
  if (this->DepthFramebuffer && window)
  {
    this->DepthFramebuffer->ReleaseGraphicsResources(window);
  }
  this->DepthFramebuffer = nullptr;
  this->ImageSampler.ReleaseGraphicsResources(window);
  if (this->Quad && window)
  {
    this->Quad->ReleaseGraphicsResources(window);
  }
  this->Quad.reset();
  this->QuadMode = -1;
  this->QuadDefines.clear();
  // Without a window (it was deleted, and its context with it) the program names are only
  // forgotten: they must not be used in the next context.
  for (unsigned int* program :
    { &this->ComputeProgram, &this->OcclusionProgram, &this->AverageProgram })
  {
    if (*program && context)
    {
      glDeleteProgram(*program);
    }
    *program = 0;
  }
  this->ComputeSupport = -1; // asked again in the next context
  this->AverageDefines.clear();
  this->SoftwareRenderer = -1;
  if (window == this->Window)
  {
    this->Window = nullptr;
  }
  if (context)
  {
    context->PopContext();
  }
}

unsigned int vtkAVSRayCaster::LightVolumeFormat() const
{
  // Transmittances in [0, 1] keep 11 significant bits as half floats, and a 64-bit texel filters
  // at twice the rate of a 128-bit one on GPUs (measured on an H100: ambient scattering with 4
  // lights 1.96 instead of 2.53 EA frames). A software rasterizer converts each half-float texel
  // instead, so there 32-bit floats are faster.
  return this->IsSoftwareRenderer() ? GL_RGBA32F : GL_RGBA16F;
}

bool vtkAVSRayCaster::IsSoftwareRenderer() const
{
  if (this->SoftwareRenderer < 0)
  {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string name = renderer ? renderer : "";
    this->SoftwareRenderer = name.find("llvmpipe") != std::string::npos ||
        name.find("softpipe") != std::string::npos || name.find("SwiftShader") != std::string::npos
      ? 1
      : 0;
  }
  return this->SoftwareRenderer == 1;
}

int vtkAVSRayCaster::MaximumTextureSize3D() const
{
  if (!this->Window)
  {
    return 0;
  }
  GLint size = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &size);
  return size;
}

bool vtkAVSRayCaster::UploadScalarGrid(vtkSmartPointer<vtkTextureObject>& texture,
  const std::array<int, 3>& d,
  int components,
  const float* data,
  std::string& error,
  unsigned int internalFormat)
{
  const int limit = this->MaximumTextureSize3D();
  if (d[0] > limit || d[1] > limit || d[2] > limit)
  {
    error = "the volume (" + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
      std::to_string(d[2]) +
      ") is too large for the GPU (largest 3D texture: " + std::to_string(limit) + " per axis)";
    return false;
  }
  // The budget of AVS_GPU_MEMORY_LIMIT_MB (vtkAVSTextureMemory.h), before anything is allocated.
  if (!vtkAVSTextureMemory::Admit(
        this->VolumeTextures(), texture, d, components, internalFormat, error))
  {
    return false;
  }
  if (texture && !data && !internalFormat &&
    texture->GetWidth() == static_cast<unsigned int>(d[0]) &&
    texture->GetHeight() == static_cast<unsigned int>(d[1]) &&
    texture->GetDepth() == static_cast<unsigned int>(d[2]) &&
    texture->GetComponents() == components)
  {
    return true; // to be written on the GPU: the storage is reused
  }
  if (texture)
  {
    texture->ReleaseGraphicsResources(this->Window);
  }
  texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(this->Window);
  ConfigureSampling(texture);
  if (internalFormat)
  {
    texture->SetInternalFormat(internalFormat);
  }
  vtkAVSRenderPasses::DiscardErrors(); // the check below is of this upload alone
  // Rows of floats are not padded.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (!texture->Create3DFromRaw(static_cast<unsigned int>(d[0]),
        static_cast<unsigned int>(d[1]),
        static_cast<unsigned int>(d[2]),
        components,
        VTK_FLOAT,
        const_cast<float*>(data)))
  {
    error = "the GPU could not allocate a " + std::to_string(d[0]) + " x " + std::to_string(d[1]) +
      " x " + std::to_string(d[2]) + " texture (out of GPU memory?)";
    texture = nullptr;
    return false;
  }
  if (glGetError() != GL_NO_ERROR)
  {
    error = "the GPU refused a 3D texture of " + std::to_string(d[0]) + " x " +
      std::to_string(d[1]) + " x " + std::to_string(d[2]) + " (out of GPU memory?)";
    texture->ReleaseGraphicsResources(this->Window);
    texture = nullptr;
    return false;
  }
  return true;
}

bool vtkAVSRayCaster::UploadScalars(const avs::VolumeScene& scene, std::string& error)
{
  const vtkAVSClassification::Layout layout = vtkAVSClassification::LayoutOf(scene);
  const std::vector<float> packed = vtkAVSClassification::PackScalars(scene, layout);
  if (!this->UploadScalarGrid(this->Scalars,
        scene.Scalars.Geometry.Dimensions,
        layout.ScalarChannels(),
        packed.data(),
        error))
  {
    return false;
  }
  this->ScalarLayout = layout;
  return true;
}

bool vtkAVSRayCaster::UploadClassification(const avs::VolumeScene& scene, std::string& error)
{
  this->Classification.SetWindow(this->Window);
  std::vector<vtkTextureObject*> held = this->VolumeTextures();
  held.resize(held.size() - this->Classification.VolumeTextures().size()); // counted by it
  return this->Classification.Upload(scene, held, error);
}

std::vector<vtkTextureObject*> vtkAVSRayCaster::VolumeTextures() const
{
  std::vector<vtkTextureObject*> held = { this->Scalars,
    this->ScalarsAveraged,
    this->AveragedExtinction,
    this->Occlusion,
    this->LightVolumes[0],
    this->LightVolumes[1],
    this->Scratch[0],
    this->Scratch[1],
    this->Scratch[2] };
  for (vtkTextureObject* t : this->Classification.VolumeTextures())
  {
    held.push_back(t); // last: UploadClassification leaves them to the classification
  }
  return held;
}

int vtkAVSRayCaster::AveragedChannelFor(const vtkAVSClassification::Layout& layout)
{
  const int k = layout.ScalarChannels();
  return k < 4 ? k : -1;
}

int vtkAVSRayCaster::AveragedComponentsFor(const vtkAVSClassification::Layout& layout)
{
  const int channel = AveragedChannelFor(layout);
  return channel < 0 ? 1 : (channel + 1 == 2 ? 2 : 4); // image formats: r32f, rg32f, rgba32f
}

bool vtkAVSRayCaster::UploadOcclusion(const avs::Grid& occlusion, std::string& error)
{
  return this->UploadScalarGrid(
    this->Occlusion, occlusion.Geometry.Dimensions, 1, occlusion.Values.data(), error);
}

bool vtkAVSRayCaster::EnsureLightTextures(const std::array<int, 3>& dimensions,
  int count,
  std::string& error)
{
  if (dimensions != this->LightTextureDimensions)
  {
    for (auto& t : this->LightVolumes)
    {
      if (t)
      {
        t->ReleaseGraphicsResources(this->Window);
      }
      t = nullptr;
    }
    this->LightTextureDimensions = dimensions;
  }
  std::vector<float> ones;
  for (int t = 0; t < count && t < NumberOfLightTextures; ++t)
  {
    if (!this->LightVolumes[t])
    {
      ones.resize(
        4 * static_cast<std::size_t>(dimensions[0]) * dimensions[1] * dimensions[2], 1.0f);
      if (!this->UploadScalarGrid(
            this->LightVolumes[t], dimensions, 4, ones.data(), error, this->LightVolumeFormat()))
      {
        this->LightTextureDimensions = { 0, 0, 0 };
        return false;
      }
    }
  }
  return true;
}

bool vtkAVSRayCaster::UploadScalarsAveraged(const avs::VolumeScene& scene,
  const avs::Grid& averagedAtVoxels,
  std::string& error)
{
  const std::size_t voxels = scene.Scalars.Values.size();
  if (averagedAtVoxels.Values.size() != voxels)
  {
    error = "the averaged extinction is not on the data's grid";
    return false;
  }
  const vtkAVSClassification::Layout layout = vtkAVSClassification::LayoutOf(scene);
  const int channel = AveragedChannelFor(layout);
  const int components = AveragedComponentsFor(layout);
  std::vector<float> packed(components * voxels, 0.0f);
  if (channel >= 0)
  {
    const int k = layout.ScalarChannels();
    const std::vector<float> scalars = vtkAVSClassification::PackScalars(scene, layout);
    for (std::size_t i = 0; i < voxels; ++i)
    {
      std::copy(&scalars[k * i], &scalars[k * i] + k, &packed[components * i]);
      packed[components * i + channel] = averagedAtVoxels.Values[i];
    }
  }
  else
  {
    packed = averagedAtVoxels.Values;
  }
  this->AveragedChannel = channel;
  return this->UploadScalarGrid(
    this->ScalarsAveraged, scene.Scalars.Geometry.Dimensions, components, packed.data(), error);
}

bool vtkAVSRayCaster::UploadLightVolumes(const std::vector<avs::Grid>& lights, std::string& error)
{
  if (lights.empty())
  {
    return true;
  }
  const avs::Grid& first = lights.front();
  const std::size_t n = first.Values.size();
  for (const avs::Grid& light : lights)
  {
    if (light.Values.size() != n)
    {
      error = "the light volumes are not on one grid";
      return false;
    }
  }
  const int textures = LightTexturesFor(static_cast<int>(lights.size()));
  for (int t = 0; t < NumberOfLightTextures; ++t)
  {
    if (t >= textures)
    {
      // Not needed now; released so that no texture of another size is left behind.
      if (this->LightVolumes[t])
      {
        this->LightVolumes[t]->ReleaseGraphicsResources(this->Window);
        this->LightVolumes[t] = nullptr;
      }
      continue;
    }
    std::vector<float> packed(4 * n, 1.0f);
    for (int c = 0; c < 4; ++c)
    {
      const std::size_t j = static_cast<std::size_t>(4 * t + c);
      if (j < lights.size())
      {
        for (std::size_t i = 0; i < n; ++i)
        {
          packed[4 * i + c] = lights[j].Values[i];
        }
      }
    }
    if (!this->UploadScalarGrid(this->LightVolumes[t],
          first.Geometry.Dimensions,
          4,
          packed.data(),
          error,
          this->LightVolumeFormat()))
    {
      return false;
    }
  }
  this->LightTextureDimensions = first.Geometry.Dimensions;
  return true;
}

bool vtkAVSRayCaster::UploadTableSlice(const avs::ScatteringSlice& slice, std::string& error)
{
  if (this->Table)
  {
    this->Table->ReleaseGraphicsResources(this->Window);
  }
  this->Table = vtkSmartPointer<vtkTextureObject>::New();
  this->Table->SetContext(this->Window);
  ConfigureSampling(this->Table);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (!this->Table->Create2DFromRaw(static_cast<unsigned int>(slice.Axes.NumberOfTheta),
        static_cast<unsigned int>(slice.Axes.NumberOfTau),
        1,
        VTK_FLOAT,
        const_cast<float*>(slice.A.data())))
  {
    error = "the GPU could not allocate the scattering-table texture";
    this->Table = nullptr;
    return false;
  }
  this->LogGain = slice.LogGain; // a uniform array of the light-volume pass
  this->TableSize[0] = static_cast<float>(slice.Axes.NumberOfTheta);
  this->TableSize[1] = static_cast<float>(slice.Axes.NumberOfTau);
  this->TableTauMaximum = static_cast<float>(slice.Axes.TauMaximum);
  return true;
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
  std::string fs = avs_raycast_fs;
  // Emission-absorption with a blend mode other than composite (vtkAVSShaderOptions).
  const bool blend = defines.find("#define AVS_BLEND ") != std::string::npos;
  std::string effect = mode == avs::RenderMode::EmissionAbsorption
    ? (blend ? avs_blend_effect : avs_ea_effect)
    : (mode == avs::RenderMode::AmbientOcclusion ? avs_ao_effect : avs_as_effect);
  std::string dec, init, sample;
  SplitEffect(effect, dec, init, sample);
  // The compile-time choices go before the first snippet that may test them.
  Replace(fs, "//AVS::Classify::Dec", defines + avs_classify);
  Replace(fs, "//AVS::Lights::Dec", avs_lights);
  Replace(fs, "//AVS::Clip::Dec", avs_clip);
  Replace(fs, "//AVS::Effect::Dec", dec);
  Replace(fs, "//AVS::Effect::Init", init);
  Replace(fs, "//AVS::Effect::Sample", sample);
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
  // The light-volume pass keeps the table's log gain in an array of this many entries.
  std::string lightVolume = avs_lightvolume_cs;
  const std::size_t line = lightVolume.find('\n') + 1; // after #version
  lightVolume.insert(line,
    "#define AVS_MAXIMUM_TAU_NODES " + std::to_string(MaximumTauNodes) + "\n" +
      "#define AVS_LIGHT_FORMAT " + (this->IsSoftwareRenderer() ? "rgba32f" : "rgba16f") + "\n");
  this->ComputeProgram = this->BuildComputeProgram(lightVolume.c_str(), "light-volume");
  this->OcclusionProgram = this->BuildComputeProgram(avs_occlusion_cs, "ambient-occlusion");
  // The averaged-extinction program depends on the classification; it is built for the
  // current one when first needed (ComputeAveragedExtinction). Here: that it compiles.
  vtkAVSClassification::Layout simplest;
  const std::string defines =
    simplest.Defines() + "#define AVS_AVERAGED_CHANNEL 1\n#define AVS_FINAL_FORMAT rg32f\n";
  this->AverageProgram = this->BuildAverageProgram(defines);
  this->ComputeSupport =
    this->ComputeProgram && this->OcclusionProgram && this->AverageProgram ? 1 : 0;
  return this->ComputeSupport == 1;
}

unsigned int vtkAVSRayCaster::BuildAverageProgram(const std::string& defines)
{
  if (this->AverageProgram && this->AverageDefines == defines)
  {
    return this->AverageProgram;
  }
  if (this->AverageProgram)
  {
    glDeleteProgram(this->AverageProgram);
    this->AverageProgram = 0;
  }
  std::string average = avs_average_cs;
  const std::size_t line = average.find('\n') + 1; // after #version
  average.insert(line, defines);
  Replace(average, "//AVS::Classify::Dec", avs_classify);
  Replace(average, "//AVS::Clip::Dec", avs_clip);
  this->AverageProgram = this->BuildComputeProgram(average.c_str(), "averaged-extinction");
  this->AverageDefines = this->AverageProgram ? defines : std::string();
  return this->AverageProgram;
}

unsigned int vtkAVSRayCaster::BuildComputeProgram(const char* source, const char* what)
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
    vtkGenericWarningMacro("The " << what
                                  << " compute shader did not compile; the precomputation runs "
                                     "on the CPU. "
                                  << log);
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

bool vtkAVSRayCaster::ComputeAveragedExtinction(const std::array<int, 3>& dimensions,
  const std::array<int, 3>& lightDimensions,
  const std::array<int, 3>& halfWidths,
  const avs::ClipRegion& clip,
  std::string& error)
{
  if (!this->SupportsComputeShaders() || !this->Scalars || !this->Classification.IsUploaded())
  {
    error = "no compute shaders, scalars or transfer function";
    return false;
  }
  // The program for this classification, and how pass 4 packs its result.
  const vtkAVSClassification::Layout& layout = this->Classification.GetLayout();
  const int channel = AveragedChannelFor(layout);
  const int components = AveragedComponentsFor(layout);
  const GLenum finalFormat = components == 1 ? GL_R32F : (components == 2 ? GL_RG32F : GL_RGBA32F);
  const std::string defines = layout.Defines() +
    (channel >= 0 ? "#define AVS_AVERAGED_CHANNEL " + std::to_string(channel) + "\n"
                  : std::string("#define AVS_AVERAGED_TEXTURE\n")) +
    "#define AVS_FINAL_FORMAT " +
    (components == 1 ? "r32f" : (components == 2 ? "rg32f" : "rgba32f")) + "\n";
  if (!this->BuildAverageProgram(defines))
  {
    error = "the averaged-extinction compute shader did not compile (see the log above)";
    return false;
  }
  // Pass 0 classifies into Scratch[0] (data grid); the x pass shrinks x to the light grid (into
  // Scratch[1]), the y pass y (into Scratch[2]), the z pass z (into AveragedExtinction); pass 4
  // writes the scalars and the averaged extinction at the voxels into ScalarsAveraged.
  const std::array<int, 3>& d = dimensions;
  const std::array<int, 3>& l = lightDimensions;
  const std::array<int, 3> shapes[4] = { d, { l[0], d[1], d[2] }, { l[0], l[1], d[2] }, l };
  vtkSmartPointer<vtkTextureObject>* images[4] = {
    &this->Scratch[0], &this->Scratch[1], &this->Scratch[2], &this->AveragedExtinction
  };
  for (int i = 0; i < 4; ++i)
  {
    if (!this->UploadScalarGrid(*images[i], shapes[i], 1, nullptr, error))
    {
      return false;
    }
  }
  if (!this->UploadScalarGrid(this->ScalarsAveraged, d, components, nullptr, error))
  {
    return false;
  }
  this->AveragedChannel = channel;
  const GLuint program = this->AverageProgram;
  vtkAVSRenderPasses::DiscardErrors(); // the check at the end is of this pass alone
  this->Window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(program);
  auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
  const double count =
    (2.0 * halfWidths[0] + 1) * (2.0 * halfWidths[1] + 1) * (2.0 * halfWidths[2] + 1);
  glUniform1f(location("u_inverseCount"), static_cast<float>(1.0 / count));
  this->SetVolumeFilter(this->Scalars, layout.Nearest);
  this->Scalars->Activate();
  glUniform1i(location("u_scalars"), this->Scalars->GetTextureUnit());
  this->Classification.Bind(program);
  vtkAVSShaderOptions::SetClipUniforms(program, clip);
  glBindImageTexture(
    2, this->ScalarsAveraged->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, finalFormat);
  for (int pass = 0; pass < 4; ++pass)
  {
    // Pass p reads images[p - 1] (pass 0: the scalars) and writes images[p].
    const std::array<int, 3>& in = pass == 0 ? d : shapes[pass - 1];
    if (pass > 0)
    {
      glBindImageTexture(0, (*images[pass - 1])->GetHandle(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
    }
    glBindImageTexture(1, (*images[pass])->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
    glUniform1i(location("u_pass"), pass);
    glUniform3i(location("u_dimensions"), in[0], in[1], in[2]);
    if (pass == 0)
    {
      glDispatchCompute(
        static_cast<GLuint>((d[0] + 7) / 8), static_cast<GLuint>((d[1] + 7) / 8), 1);
    }
    else
    {
      const int axis = pass - 1;
      const int u = axis == 0 ? in[1] : in[0];
      const int v = axis == 2 ? in[1] : in[2];
      glUniform1i(location("u_halfWidth"), halfWidths[axis]);
      glUniform1i(location("u_targetLength"), l[axis]);
      glDispatchCompute(static_cast<GLuint>((u + 7) / 8), static_cast<GLuint>((v + 7) / 8), 1);
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  }
  // Pass 4 samples AveragedExtinction as a texture: no image may write it meanwhile.
  glBindImageTexture(1, this->Scratch[0]->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  this->AveragedExtinction->Activate();
  glUniform1i(location("u_averaged"), this->AveragedExtinction->GetTextureUnit());
  glUniform3f(location("u_target"),
    static_cast<float>(l[0]),
    static_cast<float>(l[1]),
    static_cast<float>(l[2]));
  glUniform1i(location("u_pass"), 4);
  glUniform3i(location("u_dimensions"), d[0], d[1], d[2]);
  glDispatchCompute(static_cast<GLuint>((d[0] + 7) / 8), static_cast<GLuint>((d[1] + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
  this->AveragedExtinction->Deactivate();
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
  glBindImageTexture(1, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  glBindImageTexture(2, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, finalFormat);
  glUseProgram(0);
  this->Scalars->Deactivate();
  this->Classification.Unbind();
  if (const GLenum status = glGetError())
  {
    error = "the averaged-extinction compute pass failed (GL error " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

void vtkAVSRayCaster::SetVolumeFilter(vtkTextureObject* texture, bool nearest)
{
  if (texture)
  {
    const int filter = nearest ? vtkTextureObject::Nearest : vtkTextureObject::Linear;
    texture->SetMinificationFilter(filter);
    texture->SetMagnificationFilter(filter);
  }
}

bool vtkAVSRayCaster::ComputeOcclusion(const avs::Grid& extinction,
  const std::array<int, 3>& dimensions,
  double radius,
  int directions,
  std::string& error)
{
  if (!this->SupportsComputeShaders() || directions > 256)
  {
    error = "no compute shaders, or more than 256 directions";
    return false;
  }
  const avs::GridGeometry& g = extinction.Geometry;
  vtkSmartPointer<vtkTextureObject> sigma;
  if (!this->UploadScalarGrid(
        sigma, extinction.Geometry.Dimensions, 1, extinction.Values.data(), error))
  {
    return false;
  }
  if (!this->UploadScalarGrid(this->Occlusion, dimensions, 1, nullptr, error))
  {
    sigma->ReleaseGraphicsResources(this->Window);
    return false;
  }
  // The same sampling as the CPU code (Rendering/Core/AmbientOcclusion.cxx).
  const double step = 0.5 * std::min({ g.Spacing.x, g.Spacing.y, g.Spacing.z });
  const int n = std::max(1, static_cast<int>(std::ceil(radius / step)));
  const double h = radius / n;
  std::vector<float> offsets;
  for (const avs::Vec3& v : avs::SphereDirections(directions))
  {
    const avs::Vec3 l = g.WorldToLocalDirection(v);
    offsets.push_back(static_cast<float>(l.x * h / g.Spacing.x));
    offsets.push_back(static_cast<float>(l.y * h / g.Spacing.y));
    offsets.push_back(static_cast<float>(l.z * h / g.Spacing.z));
  }
  const GLuint program = this->OcclusionProgram;
  vtkAVSRenderPasses::DiscardErrors(); // the check at the end is of this pass alone
  this->Window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(program);
  auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
  glBindImageTexture(0, this->Occlusion->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  sigma->Activate();
  glUniform1i(location("u_extinction"), sigma->GetTextureUnit());
  const auto& d = g.Dimensions;
  glUniform3i(location("u_dimensions"), d[0], d[1], d[2]);
  glUniform3i(location("u_targetDimensions"), dimensions[0], dimensions[1], dimensions[2]);
  glUniform1f(location("u_border"), static_cast<float>(g.Border));
  glUniform1i(location("u_directions"), directions);
  glUniform1i(location("u_steps"), n);
  glUniform1f(location("u_step"), static_cast<float>(h));
  glUniform3fv(location("u_offsets"), directions, offsets.data());
  glDispatchCompute(static_cast<GLuint>((dimensions[0] + 7) / 8),
    static_cast<GLuint>((dimensions[1] + 7) / 8),
    static_cast<GLuint>(dimensions[2]));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  glUseProgram(0);
  sigma->Deactivate();
  sigma->ReleaseGraphicsResources(this->Window);
  if (const GLenum status = glGetError())
  {
    error = "the ambient-occlusion compute pass failed (GL error " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

bool vtkAVSRayCaster::ComputeLightVolume(int index,
  const avs::GridGeometry& lightGrid,
  const avs::Light& light,
  double radius,
  avs::TubeLaw law,
  std::string& error)
{
  if (!this->SupportsComputeShaders() || !this->AveragedExtinction || this->LogGain.size() < 2)
  {
    error = "no compute shaders, averaged extinction or table slice";
    return false;
  }
  if (this->LogGain.size() > static_cast<std::size_t>(MaximumTauNodes))
  {
    error = "the scattering table has more tau nodes than the GPU light-volume pass takes (" +
      std::to_string(MaximumTauNodes) + ")";
    return false;
  }
  const auto& d = lightGrid.Dimensions;
  // Channel c of texture t holds light 4 t + c.
  const int texture = index / 4;
  if (!this->EnsureLightTextures(d, texture + 1, error))
  {
    return false;
  }
  const GLuint program = this->ComputeProgram;
  vtkAVSRenderPasses::DiscardErrors(); // the check at the end is of this pass alone
  // The shader cache must rebind its own program afterwards.
  this->Window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(program);
  auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
  glBindImageTexture(0,
    this->LightVolumes[texture]->GetHandle(),
    0,
    GL_TRUE,
    0,
    GL_READ_WRITE,
    this->LightVolumeFormat());
  glUniform1i(location("u_channel"), index % 4);
  glUniform3i(location("u_targetDimensions"), d[0], d[1], d[2]);
  glUniform3f(location("u_targetSpacing"),
    static_cast<float>(lightGrid.Spacing.x),
    static_cast<float>(lightGrid.Spacing.y),
    static_cast<float>(lightGrid.Spacing.z));
  this->AveragedExtinction->Activate();
  glUniform1i(location("u_averaged"), this->AveragedExtinction->GetTextureUnit());
  const avs::Vec3 extent = lightGrid.LocalExtent();
  glUniform3f(location("u_extent"),
    static_cast<float>(extent.x),
    static_cast<float>(extent.y),
    static_cast<float>(extent.z));
  glUniform1fv(
    location("u_logGain"), static_cast<GLsizei>(this->LogGain.size()), this->LogGain.data());
  glUniform1i(location("u_tauNodes"), static_cast<GLint>(this->LogGain.size()));
  glUniform1f(location("u_tauMaximum"), this->TableTauMaximum);
  glUniform1f(location("u_radius"), static_cast<float>(radius));
  glUniform1i(location("u_directBeam"), law == avs::TubeLaw::DirectBeam ? 1 : 0);
  const bool positional = light.Type == avs::LightType::Positional;
  const avs::Vec3 l = positional
    ? lightGrid.WorldToLocal(light.Position)
    : lightGrid.WorldToLocalDirection(avs::Normalize(light.FocalPoint - light.Position));
  glUniform1i(location("u_positional"), positional ? 1 : 0);
  glUniform3f(
    location("u_light"), static_cast<float>(l.x), static_cast<float>(l.y), static_cast<float>(l.z));
  glDispatchCompute(static_cast<GLuint>((d[0] + 7) / 8),
    static_cast<GLuint>((d[1] + 7) / 8),
    static_cast<GLuint>(d[2]));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_WRITE, this->LightVolumeFormat());
  glUseProgram(0);
  this->AveragedExtinction->Deactivate();
  if (const GLenum status = glGetError())
  {
    error = "the light-volume compute pass failed (GL error " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

void vtkAVSRayCaster::CaptureDepth(int x, int y, int width, int height)
{
  vtkOpenGLState* state = this->Window->GetState();
  vtkAVSRenderPasses::DiscardErrors(); // the check below is of this copy alone
  // A blit from the read framebuffer (the renderer's or a render pass's) into a texture of its
  // depth format: it resolves multisampled framebuffers, and Mesa refuses glCopyTexImage2D from
  // some single-sampled ones (vtkToneMappingPass's float depth renderbuffer).
  GLint readFramebuffer = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
  const GLenum attachment = readFramebuffer ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  GLint object = GL_NONE, bits = 24, type = GL_UNSIGNED_NORMALIZED, stencil = 0;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &object);
  if (object != GL_NONE)
  {
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencil);
  }
  const int format = stencil > 0
    ? -2
    : (type == GL_FLOAT
          ? vtkTextureObject::Float32
          : (bits >= 32 ? vtkTextureObject::Fixed32
                        : (bits >= 24 ? vtkTextureObject::Fixed24 : vtkTextureObject::Fixed16)));
  if (!this->Depth || static_cast<int>(this->Depth->GetWidth()) != width ||
    static_cast<int>(this->Depth->GetHeight()) != height || format != this->DepthFormat)
  {
    if (this->Depth)
    {
      this->Depth->ReleaseGraphicsResources(this->Window);
    }
    this->Depth = vtkSmartPointer<vtkTextureObject>::New();
    this->Depth->SetContext(this->Window);
    if (format == -2)
    {
      this->Depth->AllocateDepthStencil(width, height);
    }
    else
    {
      this->Depth->AllocateDepth(width, height, format);
    }
    this->Depth->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Depth->SetWrapT(vtkTextureObject::ClampToEdge);
    this->DepthFormat = format;
  }
  if (!this->DepthFramebuffer)
  {
    this->DepthFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->DepthFramebuffer->SetContext(this->Window);
  }
  // The scissor box (the renderer's viewport) would clip the blit's destination.
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->PushFramebufferBindings();
  this->DepthFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->DepthFramebuffer->AddDepthAttachment(this->Depth);
  this->DepthFramebuffer->ActivateDrawBuffers(0);
  if (object != GL_NONE)
  {
    glBlitFramebuffer(
      x, y, x + width, y + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
  const GLenum status = glGetError();
  if (status != GL_NO_ERROR || object == GL_NONE)
  {
    // No depth, or unreadable: treat the depth as empty (no geometry) rather than leave garbage.
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  }
  state->PopFramebufferBindings();
  if (status != GL_NO_ERROR && !this->DepthWarningGiven)
  {
    vtkGenericWarningMacro("Could not copy the depth of the framebuffer (GL error "
      << status << ", depth format not matched): opaque geometry will not hide the volume.");
    this->DepthWarningGiven = true;
  }
}

bool vtkAVSRayCaster::Render(vtkRenderer* renderer, const Frame& frame, std::string& error)
{
  vtkOpenGLRenderWindow* window = this->Window;
  if (!window || !this->Scalars || !this->Classification.IsUploaded())
  {
    error = "nothing uploaded";
    return false;
  }
  const vtkAVSClassification::Layout& layout = this->Classification.GetLayout();
  if (layout.ScalarChannels() != this->ScalarLayout.ScalarChannels())
  {
    error = "the scalars and the classification do not match";
    return false;
  }
  const bool blend = frame.Mode == avs::RenderMode::EmissionAbsorption;
  if (!this->EnsureProgram(frame.Mode,
        ProgramDefines(frame, static_cast<int>(this->TableSize[1]), layout, this->AveragedChannel) +
          vtkAVSShaderOptions::ClipDefines(frame.Clip) +
          (blend ? vtkAVSShaderOptions::BlendDefines(frame.Blend) : std::string())))
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
  this->CaptureDepth(region.ReadOrigin[0], region.ReadOrigin[1], width, height);
  this->Depth->Activate();

  window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  vtkShaderProgram* program = this->Quad->Program;

  // Matrices: NDC -> world from the camera, world -> index from the mapper.
  vtkCamera* camera = renderer->GetActiveCamera();
  const double aspect = static_cast<double>(width) / std::max(1, height);
  vtkNew<vtkMatrix4x4> ndcToWorld;
  ndcToWorld->DeepCopy(camera->GetCompositeProjectionTransformMatrix(aspect, -1, 1));
  ndcToWorld->Invert();
  auto upload = [program](const char* name, vtkMatrix4x4* m)
  {
    float data[16];
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        data[c * 4 + r] = static_cast<float>(m->GetElement(r, c)); // column-major for GLSL
      }
    }
    program->SetUniformMatrix4x4(name, data);
  };
  // SetUniformMatrix4x4 sends the array as is (column-major), so GLSL sees M and M * v works.
  upload("u_ndcToWorld", ndcToWorld);
  upload("u_worldToIndex", frame.WorldToIndex);
  const float dims[3] = { static_cast<float>(frame.Dimensions[0]),
    static_cast<float>(frame.Dimensions[1]),
    static_cast<float>(frame.Dimensions[2]) };
  program->SetUniform3f("u_dimensions", dims);
  const float spacing[3] = { static_cast<float>(frame.Spacing.x),
    static_cast<float>(frame.Spacing.y),
    static_cast<float>(frame.Spacing.z) };
  program->SetUniform3f("u_spacing", spacing);
  program->SetUniformf("u_border", static_cast<float>(frame.Border));
  vtkAVSShaderOptions::SetClipUniforms(program, frame.Clip);
  if (blend)
  {
    vtkAVSShaderOptions::SetBlendUniforms(program, frame.Blend);
  }
  program->SetUniformi("u_depth", this->Depth->GetTextureUnit());
  // The volume and its classification (avs_classify.glsl), with the interpolation type's filter.
  SetVolumeFilter(this->Scalars, layout.Nearest);
  SetVolumeFilter(this->ScalarsAveraged, layout.Nearest);
  if (frame.Mode != avs::RenderMode::AmbientScattering || this->AveragedChannel < 0)
  {
    this->Scalars->Activate();
    program->SetUniformi("u_scalars", this->Scalars->GetTextureUnit());
  }
  this->Classification.Bind(static_cast<unsigned int>(program->GetHandle()));
  const avs::ScatteringParameters& p = frame.Parameters;
  program->SetUniformf("u_sampleDistance", static_cast<float>(p.SampleDistance));
  program->SetUniformf("u_termination", static_cast<float>(p.TerminationTransmittance));
  program->SetUniformi("u_jitter", frame.Jitter ? 1 : 0);

  // Lights.
  const int n = static_cast<int>(std::min<std::size_t>(frame.Lights.size(), MaximumNumberOfLights));
  float position[MaximumNumberOfLights][3] = {}, axis[MaximumNumberOfLights][3] = {},
        irradiance[MaximumNumberOfLights][3] = {}, attenuation[MaximumNumberOfLights][3] = {};
  float coneCos[MaximumNumberOfLights] = {}, exponent[MaximumNumberOfLights] = {};
  for (int j = 0; j < n; ++j)
  {
    const avs::Light& l = frame.Lights[j];
    const avs::Vec3 a = avs::Normalize(l.FocalPoint - l.Position);
    for (int k = 0; k < 3; ++k)
    {
      position[j][k] = static_cast<float>(l.Position[k]);
      axis[j][k] = static_cast<float>(a[k]);
      irradiance[j][k] = static_cast<float>(l.Irradiance[k]);
      attenuation[j][k] = static_cast<float>(l.Attenuation[k]);
    }
    coneCos[j] = l.IsSpot() ? static_cast<float>(std::cos(l.ConeAngle * avs::Pi / 180.0)) : -2.0f;
    // Not a spot: no cone and exponent 0, so the shader's spot code leaves the light unchanged.
    exponent[j] = l.IsSpot() ? static_cast<float>(l.Exponent) : 0.0f;
  }
  program->SetUniform3fv("u_lightPosition", MaximumNumberOfLights, position);
  program->SetUniform3fv("u_lightAxis", MaximumNumberOfLights, axis);
  program->SetUniform3fv("u_lightIrradiance", MaximumNumberOfLights, irradiance);
  program->SetUniform3fv("u_lightAttenuation", MaximumNumberOfLights, attenuation);
  program->SetUniform1fv("u_lightConeCos", MaximumNumberOfLights, coneCos);
  program->SetUniform1fv("u_lightExponent", MaximumNumberOfLights, exponent);

  program->SetUniformf("u_albedo", static_cast<float>(p.Albedo));
  program->SetUniformf("u_anisotropy", static_cast<float>(p.Anisotropy));
  program->SetUniformf("u_emissionWeight", static_cast<float>(p.EmissionWeight));
  if (frame.Mode == avs::RenderMode::AmbientOcclusion)
  {
    if (!this->Occlusion)
    {
      error = "no occlusion volume uploaded";
      return false;
    }
    this->Occlusion->Activate();
    program->SetUniformi("u_occlusion", this->Occlusion->GetTextureUnit());
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
    program->SetUniformf("u_ambientWeight", static_cast<float>(p.AmbientWeight));
    program->SetUniformf("u_directLightWeight", static_cast<float>(p.DirectLightWeight));
  }
  else if (frame.Mode == avs::RenderMode::AmbientScattering)
  {
    const int textures = LightTexturesFor(n);
    if (!this->Table || !this->ScalarsAveraged ||
      (textures > 0 && frame.LightVolumeDimensions != this->LightTextureDimensions) ||
      !std::all_of(this->LightVolumes,
        this->LightVolumes + textures,
        [](const vtkSmartPointer<vtkTextureObject>& t) { return t != nullptr; }))
    {
      error = "the scattering volumes are not uploaded";
      return false;
    }
    this->ScalarsAveraged->Activate();
    program->SetUniformi(this->AveragedChannel >= 0 ? "u_scalarsAveraged" : "u_averagedAtVoxels",
      this->ScalarsAveraged->GetTextureUnit());
    const char* names[NumberOfLightTextures] = { "u_lightVolumes0", "u_lightVolumes1" };
    for (int t = 0; t < textures; ++t)
    {
      this->LightVolumes[t]->Activate();
      program->SetUniformi(names[t], this->LightVolumes[t]->GetTextureUnit());
    }
    const float lvd[3] = { static_cast<float>(frame.LightVolumeDimensions[0]),
      static_cast<float>(frame.LightVolumeDimensions[1]),
      static_cast<float>(frame.LightVolumeDimensions[2]) };
    program->SetUniform3f("u_lightVolumeDimensions", lvd);
    this->Table->Activate();
    program->SetUniformi("u_table", this->Table->GetTextureUnit());
    program->SetUniform2f("u_tableSize", this->TableSize);
    program->SetUniformf("u_tableTauMaximum", this->TableTauMaximum);
    program->SetUniformf("u_ambientRadius", static_cast<float>(p.AmbientRadius));
    // The extended model (vtkAVSDiffuseVolume).
    if (p.Model == avs::ScatteringModel::Extended)
    {
      if (!this->Diffuse.IsReady())
      {
        error = "the diffuse fluence is not uploaded";
        return false;
      }
      this->Diffuse.Bind(program);
    }
  }

  // The render passes attached to the volume set what they need (vtkSSAOPass: the colour
  // target alone).
  vtkAVSRenderPasses::SetShaderParameters(frame.Prop, frame.Mapper, program);

  // Composite the premultiplied result over the framebuffer; leave depth untouched.
  {
    vtkAVSRenderPasses::ScopedCompositing compositing(state);
    vtkOpenGLState::ScopedglViewport viewportGuard(state);
    vtkAVSRenderPasses::ScopedDrawBuffer target(state, frame.PeelingFront ? 1 : 0);
    // At an image sample distance other than 1 the pass goes through an offscreen target and is
    // composited from it; at 1, or when that target cannot be made, straight into the viewport.
    vtkOpenGLShaderCache* cache = window->GetShaderCache();
    if (this->ImageSampler.Draw(window,
          x,
          y,
          width,
          height,
          frame.ImageSampleDistance,
          [&]
          {
            cache->ReadyShaderProgram(program);
            this->Quad->Render();
          }))
    {
      this->LastPassSize = { this->ImageSampler.GetTargetWidth(),
        this->ImageSampler.GetTargetHeight() };
    }
    else
    {
      state->vtkglViewport(x, y, width, height);
      this->Quad->Render();
      this->LastPassSize = { width, height };
    }
  }

  this->Classification.Unbind();
  this->Diffuse.Unbind(); // the extended model
  for (vtkTextureObject* t : { this->Depth.Get(),
         this->Scalars.Get(),
         this->Occlusion.Get(),
         this->ScalarsAveraged.Get(),
         this->LightVolumes[0].Get(),
         this->LightVolumes[1].Get(),
         this->Table.Get() })
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
  return true;
}

// The extended model's GPU diffusion solve (vtkAVSDiffuseVolume) reads these.
vtkTextureObject* vtkAVSRayCaster::GetAveragedExtinctionTexture() const
{
  return this->AveragedExtinction;
}

vtkTextureObject* vtkAVSRayCaster::GetLightVolumeTexture(int t) const
{
  return t >= 0 && t < NumberOfLightTextures ? this->LightVolumes[t].Get() : nullptr;
}
