#include "vtkAVSImageSampler.h"

#include "vtkAVSFrameUniforms.h"
#include "vtkAVSShaderAssembly.h"

#include "ImageSampleDistance.h"

#include "vtkAVSOpenGL.h"
#include "vtkObject.h" // vtkOpenGLError.h uses vtkObject without including it
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <string>

vtkAVSImageSampler::vtkAVSImageSampler() = default;

vtkAVSImageSampler::~vtkAVSImageSampler()
{
  this->ReleaseGraphicsResources(this->Window);
}

void vtkAVSImageSampler::ReleaseGraphicsResources(vtkWindow* window)
{
  if (window)
  {
    if (this->Target)
    {
      this->Target->ReleaseGraphicsResources(window);
    }
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(window);
    }
    if (this->Composite)
    {
      this->Composite->ReleaseGraphicsResources(window);
    }
  }
  this->Target = nullptr;
  this->Framebuffer = nullptr;
  this->Composite.reset();
  this->Window = nullptr;
  this->Width = this->Height = 0;
}

bool vtkAVSImageSampler::EnsureTarget(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (window != this->Window)
  {
    this->ReleaseGraphicsResources(this->Window);
    this->Window = window;
  }
  if (this->Target && static_cast<int>(this->Target->GetWidth()) == width &&
    static_cast<int>(this->Target->GetHeight()) == height)
  {
    return true;
  }
  if (this->Target)
  {
    // Another size: a new texture and a new framebuffer. (Reallocating the texture object in
    // place gives it a new GL name, and vtkOpenGLFramebufferObject does not attach the same
    // texture object again: the framebuffer kept the old, deleted name, and the pass drawn into
    // it never reached the composite. Seen as a blank volume after the target changed size.)
    this->Target->ReleaseGraphicsResources(window);
    this->Target = nullptr;
    if (this->Framebuffer)
    {
      this->Framebuffer->ReleaseGraphicsResources(window);
      this->Framebuffer = nullptr;
    }
  }
  {
    this->Target = vtkSmartPointer<vtkTextureObject>::New();
    this->Target->SetContext(window);
    // Half floats: colours above 1 survive until the blend (float framebuffers keep them).
    this->Target->SetInternalFormat(GL_RGBA16F);
    this->Target->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Target->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Target->SetMinificationFilter(vtkTextureObject::Linear);
    this->Target->SetMagnificationFilter(vtkTextureObject::Linear);
  }
  if (!this->Target->Allocate2D(
        static_cast<unsigned int>(width), static_cast<unsigned int>(height), 4, VTK_FLOAT))
  {
    this->Target = nullptr;
    return false;
  }
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(window);
  }
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->AddColorAttachment(0, this->Target);
  this->Framebuffer->ActivateDrawBuffers(1);
  const bool complete = this->Framebuffer->CheckFrameBufferStatus(GL_DRAW_FRAMEBUFFER) != 0;
  state->PopFramebufferBindings();
  if (!complete || glGetError() != GL_NO_ERROR)
  {
    this->Target->ReleaseGraphicsResources(window);
    this->Target = nullptr;
    return false;
  }
  return true;
}

bool vtkAVSImageSampler::Draw(vtkOpenGLRenderWindow* window,
  int x,
  int y,
  int width,
  int height,
  double distance,
  const std::function<void()>& pass,
  const avs::DisplayTransform& display,
  bool always)
{
  if ((distance == 1.0 && !always) || !window || width < 1 || height < 1)
  {
    return false;
  }
  GLint textureLimit = 0, viewportLimit[2] = { 0, 0 };
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &textureLimit);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewportLimit);
  const int w = std::min({ avs::SampledSize(width, distance),
    static_cast<int>(textureLimit),
    static_cast<int>(viewportLimit[0]) });
  const int h = std::min({ avs::SampledSize(height, distance),
    static_cast<int>(textureLimit),
    static_cast<int>(viewportLimit[1]) });
  if (w < 1 || h < 1 || !this->EnsureTarget(window, w, h))
  {
    if (!this->WarningGiven)
    {
      vtkGenericWarningMacro("Could not make a " << w << " x " << h
                                                 << " offscreen target for the image sample "
                                                    "distance "
                                                 << distance << ": rendering at full resolution.");
      this->WarningGiven = true;
    }
    return false;
  }
  if (!this->Composite)
  {
    const std::string fs = vtkAVSShaderAssembly::UpsampleFragmentShader();
    this->Composite = std::make_unique<vtkOpenGLQuadHelper>(window, nullptr, fs.c_str(), "");
    if (!this->Composite->Program || !this->Composite->Program->GetCompiled())
    {
      this->Composite.reset();
      if (!this->WarningGiven)
      {
        vtkGenericWarningMacro("The image-sample compositing shader did not compile: rendering "
                               "at full resolution.");
        this->WarningGiven = true;
      }
      return false;
    }
  }
  this->Width = w;
  this->Height = h;
  vtkOpenGLState* state = window->GetState();

  // The pass into the target: cleared to "nothing" (transparent black), so that the blend the
  // caller set leaves each ray's premultiplied colour and opacity as they are.
  {
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglClearColor clearColor(state);
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    state->PushFramebufferBindings();
    this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
    this->Framebuffer->ActivateDrawBuffers(1);
    state->vtkglDisable(GL_SCISSOR_TEST); // the renderer's scissor box is in window pixels
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    state->vtkglViewport(0, 0, w, h);
    state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
    pass();
    state->PopFramebufferBindings();
  }

  // Composite over the viewport of the framebuffer bound before.
  window->GetShaderCache()->ReadyShaderProgram(this->Composite->Program);
  this->Target->Activate();
  this->Composite->Program->SetUniformi("u_sampled", this->Target->GetTextureUnit());
  vtkAVSFrameUniforms::SetDisplay(this->Composite->Program, display);
  state->vtkglViewport(x, y, width, height);
  this->Composite->Render();
  this->Target->Deactivate();
  vtkOpenGLStaticCheckErrorMacro("failed after compositing the sampled pass");
  return true;
}
