#include "vtkAVSOcclusionPass.h"

#include "vtkAVSRenderPasses.h"
#include "vtkAVSShaderAssembly.h"
#include "vtkAVSShaders.h"
#include "vtkAVSVolumeTextures.h"

#include "AmbientOcclusion.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <vector>

bool vtkAVSOcclusionPass::Build()
{
  this->Program = vtkAVSShaderAssembly::BuildComputeProgram(avs_occlusion_cs, "ambient-occlusion");
  return this->Program != 0;
}

void vtkAVSOcclusionPass::ReleaseGraphicsResources(bool context)
{
  vtkAVSShaderAssembly::ReleaseComputeProgram(this->Program, context);
}

bool vtkAVSOcclusionPass::Run(vtkAVSVolumeTextures& textures,
  const avs::GridGeometry& g,
  vtkTextureObject* sigma,
  const std::array<int, 3>& dimensions,
  double radius,
  int directions,
  std::string& error)
{
  if (!textures.UploadGrid(textures.Occlusion, dimensions, 1, nullptr, error))
  {
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
  const GLuint program = this->Program;
  vtkAVSRenderPasses::DiscardErrors(); // the check at the end is of this pass alone
  textures.Window->GetShaderCache()->ReleaseCurrentShader();
  glUseProgram(program);
  auto location = [program](const char* name) { return glGetUniformLocation(program, name); };
  glBindImageTexture(0, textures.Occlusion->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
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
  // A dispatch that does nothing, with sigma_t's unit emptied: Mesa keeps the textures of the
  // last dispatch referenced until the next one, so without it the caller's release of sigma_t
  // (4 bytes per voxel) would not free its storage until the next compute pass (measured on
  // llvmpipe: 530 MiB held at 512^3 after the pass, and twice that at the next rebuild).
  vtkOpenGLState* state = textures.Window->GetState();
  state->vtkglActiveTexture(GL_TEXTURE0 + sigma->GetTextureUnit());
  glBindTexture(GL_TEXTURE_3D, 0);
  glUniform3i(location("u_targetDimensions"), 0, 0, 0);
  glDispatchCompute(1, 1, 1);
  glUseProgram(0);
  sigma->Deactivate();
  if (const GLenum status = glGetError())
  {
    error = "the ambient-occlusion compute pass failed (GL error " + std::to_string(status) + ")";
    return false;
  }
  return true;
}
