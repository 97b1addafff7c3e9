#include "vtkAVSAveragedExtinctionPass.h"

#include "vtkAVSRenderPasses.h"
#include "vtkAVSShaderAssembly.h"
#include "vtkAVSShaderOptions.h"
#include "vtkAVSVolumeTextures.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

double vtkAVSAveragedExtinctionPass::SlabBytes()
{
  const char* value = std::getenv("AVS_AVERAGING_SLAB_BYTES");
  const double bytes = value ? std::atof(value) : 0.0;
  return bytes > 0.0 ? bytes : 16.0 * 1024 * 1024;
}

int vtkAVSAveragedExtinctionPass::MaximumWindowRing()
{
  const char* value = std::getenv("AVS_AVERAGING_WINDOW_RING");
  return value ? std::max(0, std::atoi(value)) : 256;
}

int vtkAVSAveragedExtinctionPass::WindowRing(int halfWidth)
{
  const int most = MaximumWindowRing();
  int ring = 2;
  while (ring < 2 * halfWidth + 2 && ring <= most)
  {
    ring *= 2;
  }
  return ring <= most ? ring : 0;
}

unsigned int vtkAVSAveragedExtinctionPass::Build(const vtkAVSClassification::Layout& layout,
  int halfWidth)
{
  const std::string defines = layout.Defines();
  // A ring serves every window narrower than it: built again only for a wider one.
  const int needed = WindowRing(halfWidth);
  const bool serves = needed == 0 ? this->Ring == 0 : this->Ring >= needed;
  if (this->Program[0] && this->Program[1] && this->Defines == defines && serves)
  {
    return this->Program[0];
  }
  this->ReleaseGraphicsResources(true);
  this->Program[0] = vtkAVSShaderAssembly::BuildComputeProgram(
    vtkAVSShaderAssembly::AveragedExtinctionShader(defines + "#define AVS_AVERAGE_CLASSIFY\n" +
      "#define AVS_AVERAGE_RING " + std::to_string(needed) + "\n")
      .c_str(),
    "averaged-extinction");
  this->Program[1] = vtkAVSShaderAssembly::BuildComputeProgram(
    vtkAVSShaderAssembly::AveragedExtinctionShader(defines).c_str(), "averaged-extinction");
  if (!this->Program[0] || !this->Program[1])
  {
    this->ReleaseGraphicsResources(true);
    return 0;
  }
  this->Defines = defines;
  this->Ring = needed;
  return this->Program[0];
}

void vtkAVSAveragedExtinctionPass::ReleaseGraphicsResources(bool context)
{
  vtkAVSShaderAssembly::ReleaseComputeProgram(this->Program[0], context);
  vtkAVSShaderAssembly::ReleaseComputeProgram(this->Program[1], context);
  this->Defines.clear();
  this->Ring = 0;
}

bool vtkAVSAveragedExtinctionPass::Begin(vtkAVSVolumeTextures& textures,
  const avs::ClipRegion& clip,
  int halfWidth,
  double inverseCount,
  std::string& error)
{
  // The program for this classification and pass 1's window.
  const vtkAVSClassification::Layout& layout = textures.Classification.GetLayout();
  if (!this->Build(layout, halfWidth))
  {
    error = "the averaged-extinction compute shader did not compile (see the log above)";
    return false;
  }
  vtkAVSRenderPasses::DiscardErrors(); // the check at the end is of this pass alone
  textures.Window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(this->Program[1]);
  glUniform1f(
    glGetUniformLocation(this->Program[1], "u_inverseCount"), static_cast<float>(inverseCount));
  const GLuint program = this->Program[0];
  glUseProgram(program);
  vtkAVSVolumeTextures::SetVolumeFilter(textures.Scalars, layout.Nearest);
  textures.Scalars->Activate();
  glUniform1i(glGetUniformLocation(program, "u_scalars"), textures.Scalars->GetTextureUnit());
  textures.Classification.Bind(program);
  vtkAVSShaderOptions::SetClipUniforms(program, clip);
  return true;
}

void vtkAVSAveragedExtinctionPass::Dispatch(int pass,
  vtkTextureObject* input,
  vtkTextureObject* output,
  const std::array<int, 3>& in,
  int zOffset,
  int halfWidth,
  int targetLength)
{
  const GLuint program = this->Program[pass == 1 ? 0 : 1];
  glUseProgram(program);
  auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
  glBindImageTexture(0, input ? input->GetHandle() : 0, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
  glBindImageTexture(1, output->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  glUniform1i(location("u_pass"), pass);
  glUniform1i(location("u_zOffset"), zOffset);
  glUniform3i(location("u_dimensions"), in[0], in[1], in[2]);
  const int axis = pass - 1;
  const int u = axis == 0 ? in[1] : in[0];
  const int v = axis == 2 ? in[1] : in[2];
  glUniform1i(location("u_halfWidth"), halfWidth);
  glUniform1i(location("u_targetLength"), targetLength);
  glDispatchCompute(static_cast<GLuint>((u + 7) / 8), static_cast<GLuint>((v + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

bool vtkAVSAveragedExtinctionPass::End(vtkAVSVolumeTextures& textures, std::string& error)
{
  glBindImageTexture(0, 0, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
  glBindImageTexture(1, 0, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  glUseProgram(0);
  textures.Scalars->Deactivate();
  textures.Classification.Unbind();
  if (const GLenum status = glGetError())
  {
    error = "the averaged-extinction compute pass failed (GL error " + std::to_string(status) + ")";
    return false;
  }
  return true;
}

bool vtkAVSAveragedExtinctionPass::Run(vtkAVSVolumeTextures& textures,
  const std::array<int, 3>& dimensions,
  const std::array<int, 3>& lightDimensions,
  const std::array<int, 3>& halfWidths,
  const avs::ClipRegion& clip,
  std::string& error)
{
  // The x pass classifies the scalars as it sums them and shrinks x to the light grid (into
  // Scratch[0]), the y pass y (into Scratch[1]), the z pass z (into AveragedExtinction), which
  // the light-volume pass and the ray caster sample. (A classification pass of its own would
  // need sigma_t on the data grid, 4 bytes per voxel.)
  // Passes 1 and 2 go slab by slab along z, so that Scratch[0] holds one slab (of at most
  // SlabBytes) rather than l0 x d1 x d2 floats, which is the rebuild's largest grid otherwise.
  const std::array<int, 3>& d = dimensions;
  const std::array<int, 3>& l = lightDimensions;
  const double sliceBytes = 4.0 * l[0] * d[1];
  const int slab =
    static_cast<int>(std::clamp(std::floor(SlabBytes() / sliceBytes), 1.0, double(d[2])));
  const std::array<int, 3> shapes[4] = { d, { l[0], d[1], slab }, { l[0], l[1], d[2] }, l };
  vtkSmartPointer<vtkTextureObject>* images[4] = {
    nullptr, &textures.Scratch[0], &textures.Scratch[1], &textures.AveragedExtinction
  };
  for (int i = 1; i < 4; ++i)
  {
    if (!textures.UploadGrid(*images[i], shapes[i], 1, nullptr, error))
    {
      return false;
    }
  }
  ++textures.AveragedWrites;
  const double count =
    (2.0 * halfWidths[0] + 1) * (2.0 * halfWidths[1] + 1) * (2.0 * halfWidths[2] + 1);
  if (!this->Begin(textures, clip, halfWidths[0], 1.0 / count, error))
  {
    return false;
  }
  // Pass p reads images[p - 1] (pass 1: the scalars, classified) over `in` and writes images[p].
  auto run = [&](int pass, const std::array<int, 3>& in, int zOffset)
  {
    this->Dispatch(pass,
      pass > 1 ? images[pass - 1]->Get() : nullptr,
      *images[pass],
      in,
      zOffset,
      halfWidths[pass - 1],
      l[pass - 1]);
  };
  for (int z0 = 0; z0 < d[2]; z0 += slab)
  {
    const int depth = std::min(slab, d[2] - z0);
    run(1, { d[0], d[1], depth }, z0);
    run(2, { l[0], d[1], depth }, z0);
  }
  run(3, shapes[2], 0);
  const bool ok = this->End(textures, error);
  // Not kept for the next rebuild (the memory of a volume at rest is the scalars and
  // the light grid's volumes); allocating them again costs a little on a software rasterizer.
  textures.ReleaseScratch();
  return ok;
}

bool vtkAVSAveragedExtinctionPass::Classify(vtkAVSVolumeTextures& textures,
  const std::array<int, 3>& dimensions,
  const avs::ClipRegion& clip,
  vtkTextureObject* target,
  std::string& error)
{
  // Pass 1 with a window of one voxel and no shrinking: sigma_t at each voxel.
  if (!this->Begin(textures, clip, 0, 1.0, error))
  {
    return false;
  }
  this->Dispatch(1, nullptr, target, dimensions, 0, 0, dimensions[0]);
  return this->End(textures, error);
}
