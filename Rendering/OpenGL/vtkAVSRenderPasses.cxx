#include "vtkAVSRenderPasses.h"

#include "vtkAVSOpenGL.h"
#include "vtkAbstractMapper.h"
#include "vtkCameraPass.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSSAAPass.h"
#include "vtkSequencePass.h"
#include "vtkToneMappingPass.h"

#include <algorithm>
#include <string>

namespace
{
// The render passes attached to a prop, or none.
int PassCount(vtkInformation* info)
{
  return info && info->Has(vtkOpenGLRenderPass::RenderPasses())
    ? info->Length(vtkOpenGLRenderPass::RenderPasses())
    : 0;
}

vtkOpenGLRenderPass* PassAt(vtkInformation* info, int i)
{
  return vtkOpenGLRenderPass::SafeDownCast(info->Get(vtkOpenGLRenderPass::RenderPasses(), i));
}
// Whether `pass` is, or delegates to, a vtkToneMappingPass (depth-limited against cycles).
bool HasToneMapping(vtkRenderPass* pass, int depth)
{
  if (!pass || depth > 16)
  {
    return false;
  }
  if (vtkToneMappingPass::SafeDownCast(pass))
  {
    return true;
  }
  if (auto* camera = vtkCameraPass::SafeDownCast(pass))
  {
    return HasToneMapping(camera->GetDelegatePass(), depth + 1);
  }
  if (auto* image = vtkImageProcessingPass::SafeDownCast(pass))
  {
    return HasToneMapping(image->GetDelegatePass(), depth + 1);
  }
  if (auto* ssaa = vtkSSAAPass::SafeDownCast(pass))
  {
    return HasToneMapping(ssaa->GetDelegatePass(), depth + 1);
  }
  if (auto* steps = vtkRenderStepsPass::SafeDownCast(pass))
  {
    return HasToneMapping(steps->GetPostProcessPass(), depth + 1);
  }
  if (auto* sequence = vtkSequencePass::SafeDownCast(pass))
  {
    vtkRenderPassCollection* passes = sequence->GetPasses();
    for (int i = 0; passes && i < passes->GetNumberOfItems(); ++i)
    {
      if (HasToneMapping(vtkRenderPass::SafeDownCast(passes->GetItemAsObject(i)), depth + 1))
      {
        return true;
      }
    }
  }
  return false;
}
} // namespace

bool vtkAVSRenderPasses::UnderToneMapping(vtkRenderer* renderer)
{
  return renderer && HasToneMapping(renderer->GetPass(), 0);
}

vtkAVSRenderPasses::Role vtkAVSRenderPasses::RoleOf(vtkProp* prop, vtkAbstractMapper* mapper)
{
  vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
  const int n = PassCount(info);
  for (int i = 0; i < n; ++i)
  {
    auto* peeling = vtkDualDepthPeelingPass::SafeDownCast(PassAt(info, i));
    if (!peeling)
    {
      continue;
    }
    // The pass calls the volumes first before peeling (its InitializingDepth stage: front and
    // back targets empty, the volume's parts in front of and behind all translucent layers
    // wanted), then once per peel and at the end. Its stage is protected; it shows in the
    // declarations the pass gives a volume shader: the depth textures of the first stage, the
    // last front colour as well in the peels, a depth range in the final blend.
    std::string vertex, geometry, fragment = "//VTK::DepthPeeling::Dec";
    peeling->PreReplaceShaderValues(vertex, geometry, fragment, mapper, prop);
    const bool first = fragment.find("innerDepthTex") != std::string::npos &&
      fragment.find("lastFrontColorTex") == std::string::npos;
    return first ? Role::PeelingFront : Role::Skip;
  }
  return Role::Composite;
}

void vtkAVSRenderPasses::SetShaderParameters(vtkProp* prop,
  vtkAbstractMapper* mapper,
  vtkShaderProgram* program)
{
  vtkInformation* info = prop ? prop->GetPropertyKeys() : nullptr;
  const int n = PassCount(info);
  for (int i = 0; i < n; ++i)
  {
    if (vtkOpenGLRenderPass* pass = PassAt(info, i))
    {
      // The result says whether the pass found its uniforms; the ray caster declares none of
      // them (vtkDualDepthPeelingPass's depth textures, for one), so it is not an error here.
      pass->SetShaderParameters(program, mapper, prop, nullptr);
    }
  }
}

int vtkAVSRenderPasses::DiscardErrors()
{
  int count = 0;
  while (count < 16 && glGetError() != GL_NO_ERROR)
  {
    ++count;
  }
  return count;
}

vtkAVSRenderPasses::Region vtkAVSRenderPasses::Locate(vtkOpenGLRenderWindow* window,
  vtkRenderer* renderer)
{
  Region region;
  window->GetState()->vtkglGetIntegerv(GL_VIEWPORT, region.Draw.data());
  region.Draw[2] = std::max(1, region.Draw[2]);
  region.Draw[3] = std::max(1, region.Draw[3]);
  GLint read = 0, draw = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
  if (read == draw)
  {
    region.ReadOrigin = { region.Draw[0], region.Draw[1] };
    return region;
  }
  // Drawing into a pass's framebuffer while the depth comes from another one
  // (vtkDualDepthPeelingPass reads the opaque depth where the renderer's picture is).
  vtkOpenGLFramebufferObject* own = window->GetRenderFramebuffer();
  if (read == 0 || (own && static_cast<unsigned int>(read) == own->GetFBOIndex()))
  {
    int width, height;
    renderer->GetTiledSizeAndOrigin(&width, &height, &region.ReadOrigin[0], &region.ReadOrigin[1]);
  }
  else
  {
    region.ReadOrigin = { 0, 0 };
  }
  return region;
}

vtkAVSRenderPasses::ScopedCompositing::ScopedCompositing(vtkOpenGLState* state)
  : State(state)
{
  this->Blend = state->GetEnumState(GL_BLEND);
  this->DepthTest = state->GetEnumState(GL_DEPTH_TEST);
  this->Cull = state->GetEnumState(GL_CULL_FACE);
  state->vtkglGetBooleanv(GL_DEPTH_WRITEMASK, &this->DepthMask);
  state->vtkglGetIntegerv(GL_BLEND_EQUATION_RGB, &this->Equation[0]);
  state->vtkglGetIntegerv(GL_BLEND_EQUATION_ALPHA, &this->Equation[1]);
  state->GetBlendFuncState(this->Function);
  // Premultiplied colour over what is there; vtkDualDepthPeelingPass leaves GL_MAX blending and
  // back-face culling on when it calls the volumes.
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendEquation(GL_FUNC_ADD);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglDisable(GL_CULL_FACE);
}

vtkAVSRenderPasses::ScopedCompositing::~ScopedCompositing()
{
  vtkOpenGLState* state = this->State;
  state->vtkglBlendFuncSeparate(static_cast<unsigned int>(this->Function[0]),
    static_cast<unsigned int>(this->Function[1]),
    static_cast<unsigned int>(this->Function[2]),
    static_cast<unsigned int>(this->Function[3]));
  state->vtkglBlendEquationSeparate(
    static_cast<unsigned int>(this->Equation[0]), static_cast<unsigned int>(this->Equation[1]));
  state->vtkglDepthMask(this->DepthMask);
  state->SetEnumState(GL_CULL_FACE, this->Cull);
  state->SetEnumState(GL_DEPTH_TEST, this->DepthTest);
  state->SetEnumState(GL_BLEND, this->Blend);
}

vtkAVSRenderPasses::ScopedDrawBuffer::ScopedDrawBuffer(vtkOpenGLState* state, int which)
  : State(state)
{
  GLint most = 1;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &most);
  most = std::min<GLint>(most, MaximumBuffers);
  for (int i = 0; i < most; ++i)
  {
    GLint buffer = GL_NONE;
    glGetIntegerv(GL_DRAW_BUFFER0 + i, &buffer);
    this->Buffers[i] = static_cast<unsigned int>(buffer);
    this->Count = buffer != GL_NONE ? i + 1 : this->Count;
  }
  this->Changed = (this->Count > 1 || which != 0) && which < this->Count;
  if (this->Changed)
  {
    unsigned int only = this->Buffers[which];
    SetDrawBuffers(state, 1, &only);
  }
}

vtkAVSRenderPasses::ScopedDrawBuffer::~ScopedDrawBuffer()
{
  if (this->Changed)
  {
    SetDrawBuffers(this->State, this->Count, this->Buffers);
  }
}

void vtkAVSRenderPasses::ScopedDrawBuffer::SetDrawBuffers(vtkOpenGLState* state,
  int count,
  unsigned int* buffers)
{
  // vtkOpenGLState compares only the first `count` entries with its cache, so going from three
  // buffers to one with the same first entry (vtkSSAOPass's ActivateDrawBuffers(1)) or back
  // would not reach OpenGL; a GL_NONE first makes both calls real and keeps the cache right.
  unsigned int none = GL_NONE;
  state->vtkglDrawBuffers(1, &none);
  state->vtkglDrawBuffers(static_cast<unsigned int>(count), buffers);
}
