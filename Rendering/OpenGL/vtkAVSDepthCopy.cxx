#include "vtkAVSDepthCopy.h"

#include "vtkAVSRenderPasses.h"

#include "vtkAVSOpenGL.h"
#include "vtkObject.h" // for vtkGenericWarningMacro
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"

vtkAVSDepthCopy::vtkAVSDepthCopy() = default;

vtkAVSDepthCopy::~vtkAVSDepthCopy() = default;

void vtkAVSDepthCopy::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Depth && window)
  {
    this->Depth->ReleaseGraphicsResources(window);
  }
  this->Depth = nullptr;
  if (this->Framebuffer && window)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Framebuffer = nullptr;
}

void vtkAVSDepthCopy::Capture(vtkOpenGLRenderWindow* window, int x, int y, int width, int height)
{
  vtkOpenGLState* state = window->GetState();
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
    static_cast<int>(this->Depth->GetHeight()) != height || format != this->Format)
  {
    if (this->Depth)
    {
      this->Depth->ReleaseGraphicsResources(window);
    }
    this->Depth = vtkSmartPointer<vtkTextureObject>::New();
    this->Depth->SetContext(window);
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
    this->Format = format;
  }
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(window);
  }
  // The scissor box (the renderer's viewport) would clip the blit's destination.
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->PushFramebufferBindings();
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->AddDepthAttachment(this->Depth);
  this->Framebuffer->ActivateDrawBuffers(0);
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
  if (status != GL_NO_ERROR && !this->WarningGiven)
  {
    vtkGenericWarningMacro("Could not copy the depth of the framebuffer (GL error "
      << status << ", depth format not matched): opaque geometry will not hide the volume.");
    this->WarningGiven = true;
  }
}
