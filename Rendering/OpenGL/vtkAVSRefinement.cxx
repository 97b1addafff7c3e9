#include "vtkAVSRefinement.h"

#include "vtkAVSFrameUniforms.h"
#include "vtkAVSShaderAssembly.h"

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
#include <cmath>
#include <cstddef>

namespace
{
// A width x height RGBA texture of 32-bit floats, read texel by texel.
vtkSmartPointer<vtkTextureObject> FloatTarget(vtkOpenGLRenderWindow* window, int width, int height)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetInternalFormat(GL_RGBA32F);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!texture->Allocate2D(
        static_cast<unsigned int>(width), static_cast<unsigned int>(height), 4, VTK_FLOAT))
  {
    return nullptr;
  }
  return texture;
}

// A framebuffer that draws into `targets` (attachments 0, 1, ...); null when incomplete.
vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer(vtkOpenGLRenderWindow* window,
  const std::vector<vtkTextureObject*>& targets)
{
  auto framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  framebuffer->SetContext(window);
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  for (std::size_t i = 0; i < targets.size(); ++i)
  {
    framebuffer->AddColorAttachment(static_cast<unsigned int>(i), targets[i]);
  }
  framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(targets.size()));
  const bool complete = framebuffer->CheckFrameBufferStatus(GL_DRAW_FRAMEBUFFER) != 0;
  state->PopFramebufferBindings();
  if (!complete || glGetError() != GL_NO_ERROR)
  {
    framebuffer->ReleaseGraphicsResources(window);
    return nullptr;
  }
  return framebuffer;
}

// Draws into `framebuffer` (its `buffers` attachments, the whole of its width x height) with
// the scissor test off and every channel written; `draw` does the drawing.
void DrawInto(vtkOpenGLRenderWindow* window,
  vtkOpenGLFramebufferObject* framebuffer,
  int buffers,
  int width,
  int height,
  const std::function<void()>& draw)
{
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglViewport viewport(state);
  state->PushFramebufferBindings();
  framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(buffers));
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglViewport(0, 0, width, height);
  draw();
  state->PopFramebufferBindings();
}

// Whether the geometric parts of two keys agree to a millionth: VTK computes the same camera's
// matrix with other last digits from one render to the next (vtkWindowToImageFilter's render
// sets the view angle through a tangent and back).
bool Near(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    if (!(std::abs(a[i] - b[i]) <= 1e-6 * std::max({ 1.0, std::abs(a[i]), std::abs(b[i]) })))
    {
      return false;
    }
  }
  return true;
}

// The texture unit of `texture`, activated.
int Unit(vtkTextureObject* texture)
{
  texture->Activate();
  return texture->GetTextureUnit();
}
} // namespace

vtkAVSRefinement::vtkAVSRefinement() = default;

vtkAVSRefinement::~vtkAVSRefinement()
{
  this->ReleaseGraphicsResources(this->Window);
}

void vtkAVSRefinement::ReleaseGraphicsResources(vtkWindow* window)
{
  if (window)
  {
    for (vtkTextureObject* t :
      { this->Sum.Get(), this->SumSquares.Get(), this->Ambient.Get(), this->Majorants.Get() })
    {
      if (t)
      {
        t->ReleaseGraphicsResources(window);
      }
    }
    for (vtkOpenGLFramebufferObject* f : { this->Accumulation.Get(), this->AmbientTarget.Get() })
    {
      if (f)
      {
        f->ReleaseGraphicsResources(window);
      }
    }
    for (vtkOpenGLQuadHelper* q : { this->PathTracer.get(), this->Picture.get() })
    {
      if (q)
      {
        q->ReleaseGraphicsResources(window);
      }
    }
  }
  this->Sum = this->SumSquares = this->Ambient = this->Majorants = nullptr;
  this->Accumulation = this->AmbientTarget = nullptr;
  this->PathTracer.reset();
  this->Picture.reset();
  this->PathTracerDefines.clear();
  this->Key.clear();
  this->Geometry.clear();
  this->MajorantsVersion = -1;
  this->Window = nullptr;
  this->Width = this->Height = 0;
  this->Samples = 0;
  this->AmbientHeld = false;
}

bool vtkAVSRefinement::EnsureBuffers(int width, int height, std::string& error)
{
  if (this->Sum && this->Width == width && this->Height == height)
  {
    return true;
  }
  vtkOpenGLRenderWindow* window = this->Window;
  // Another size: new textures and framebuffers (vtkOpenGLFramebufferObject does not attach a
  // texture object again once it has a new GL name; see vtkAVSImageSampler).
  this->ReleaseGraphicsResources(window);
  this->Window = window;
  this->Sum = FloatTarget(window, width, height);
  this->SumSquares = this->Sum ? FloatTarget(window, width, height) : nullptr;
  this->Ambient = this->SumSquares ? FloatTarget(window, width, height) : nullptr;
  if (this->Ambient)
  {
    this->Accumulation = Framebuffer(window, { this->Sum, this->SumSquares });
    this->AmbientTarget = Framebuffer(window, { this->Ambient });
  }
  if (!this->Accumulation || !this->AmbientTarget)
  {
    this->ReleaseGraphicsResources(window);
    this->Window = window;
    error = "the path-traced refinement could not make its " + std::to_string(width) + " x " +
      std::to_string(height) + " float buffers";
    return false;
  }
  this->Width = width;
  this->Height = height;
  return true;
}

void vtkAVSRefinement::Clear()
{
  DrawInto(this->Window,
    this->Accumulation,
    2,
    this->Width,
    this->Height,
    [this]
    {
      vtkOpenGLState* state = this->Window->GetState();
      vtkOpenGLState::ScopedglClearColor clearColor(state);
      state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      state->vtkglClear(GL_COLOR_BUFFER_BIT);
    });
  this->Samples = 0;
  this->AmbientHeld = false;
}

bool vtkAVSRefinement::Begin(vtkOpenGLRenderWindow* window,
  int width,
  int height,
  const std::vector<double>& key,
  const std::vector<double>& geometry,
  std::string& error)
{
  if (window != this->Window)
  {
    this->ReleaseGraphicsResources(this->Window);
    this->Window = window;
  }
  if (!window || width < 1 || height < 1)
  {
    error = "no window or an empty viewport";
    return false;
  }
  const bool resized = this->Width != width || this->Height != height || !this->Sum;
  if (!this->EnsureBuffers(width, height, error))
  {
    return false;
  }
  if (resized || key != this->Key || !Near(geometry, this->Geometry) || this->Key.empty())
  {
    this->Key = key;
    this->Geometry = geometry;
    this->Clear();
  }
  return true;
}

void vtkAVSRefinement::Reset()
{
  // The float buffers (48 bytes a pixel) are not kept for a volume that is not refined; the
  // programs and the majorants are.
  vtkOpenGLRenderWindow* window = this->Window;
  if (window)
  {
    for (vtkTextureObject* t : { this->Sum.Get(), this->SumSquares.Get(), this->Ambient.Get() })
    {
      if (t)
      {
        t->ReleaseGraphicsResources(window);
      }
    }
    for (vtkOpenGLFramebufferObject* f : { this->Accumulation.Get(), this->AmbientTarget.Get() })
    {
      if (f)
      {
        f->ReleaseGraphicsResources(window);
      }
    }
  }
  this->Sum = this->SumSquares = this->Ambient = nullptr;
  this->Accumulation = this->AmbientTarget = nullptr;
  this->Width = this->Height = 0;
  this->Key.clear();
  this->Geometry.clear();
  this->Samples = 0;
  this->AmbientHeld = false;
}

void vtkAVSRefinement::CaptureAmbient(const std::function<void()>& pass)
{
  DrawInto(this->Window,
    this->AmbientTarget,
    1,
    this->Width,
    this->Height,
    [&]
    {
      vtkOpenGLState* state = this->Window->GetState();
      vtkOpenGLState::ScopedglClearColor clearColor(state);
      state->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      state->vtkglClear(GL_COLOR_BUFFER_BIT);
      pass();
    });
  this->AmbientHeld = true;
}

bool vtkAVSRefinement::UpdateMajorants(const std::vector<float>& values,
  const std::array<int, 3>& cells,
  int version,
  std::string& error)
{
  if (this->Majorants && version == this->MajorantsVersion && cells == this->MajorantCells)
  {
    return true;
  }
  const std::size_t count = static_cast<std::size_t>(cells[0]) * cells[1] * cells[2];
  if (count == 0 || values.size() != count)
  {
    error = "no majorants of the volume's cells";
    return false;
  }
  if (this->Majorants)
  {
    this->Majorants->ReleaseGraphicsResources(this->Window);
  }
  this->Majorants = vtkSmartPointer<vtkTextureObject>::New();
  this->Majorants->SetContext(this->Window);
  this->Majorants->SetInternalFormat(GL_R32F);
  this->Majorants->SetFormat(GL_RED);
  this->Majorants->SetDataType(GL_FLOAT);
  this->Majorants->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Majorants->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Majorants->SetWrapR(vtkTextureObject::ClampToEdge);
  this->Majorants->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Majorants->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!this->Majorants->Create3DFromRaw(static_cast<unsigned int>(cells[0]),
        static_cast<unsigned int>(cells[1]),
        static_cast<unsigned int>(cells[2]),
        1,
        VTK_FLOAT,
        const_cast<float*>(values.data())))
  {
    this->Majorants = nullptr;
    error = "the majorants of the path-traced refinement could not be uploaded";
    return false;
  }
  this->MajorantCells = cells;
  this->MajorantsVersion = version;
  return true;
}

bool vtkAVSRefinement::AddSample(const std::string& defines,
  const std::function<void(vtkShaderProgram*)>& setUniforms,
  std::string& error)
{
  vtkOpenGLRenderWindow* window = this->Window;
  if (!window || !this->Accumulation || !this->Majorants)
  {
    error = "the path-traced refinement has no buffers or majorants";
    return false;
  }
  if (!this->PathTracer || defines != this->PathTracerDefines)
  {
    if (this->PathTracer)
    {
      this->PathTracer->ReleaseGraphicsResources(window);
    }
    const std::string fs = vtkAVSShaderAssembly::PathTraceFragmentShader(defines);
    this->PathTracer = std::make_unique<vtkOpenGLQuadHelper>(window, nullptr, fs.c_str(), "");
    this->PathTracerDefines = defines;
    if (!this->PathTracer->Program || !this->PathTracer->Program->GetCompiled())
    {
      this->PathTracer.reset();
      this->PathTracerDefines.clear();
      error = "the path-tracing shader did not compile or link (see the log above)";
      return false;
    }
  }
  vtkShaderProgram* program = this->PathTracer->Program;
  window->GetShaderCache()->ReadyShaderProgram(program);
  program->SetUniformi("u_majorants", Unit(this->Majorants));
  const float cells[3] = { static_cast<float>(this->MajorantCells[0]),
    static_cast<float>(this->MajorantCells[1]),
    static_cast<float>(this->MajorantCells[2]) };
  program->SetUniform3f("u_majorantCells", cells);
  const float size[2] = { static_cast<float>(this->Width), static_cast<float>(this->Height) };
  program->SetUniform2f("u_viewportSize", size);
  program->SetUniformi("u_sampleIndex", this->Samples);
  program->SetUniformi("u_seed", 1);
  setUniforms(program);
  vtkOpenGLState* state = window->GetState();
  int function[4];
  state->GetBlendFuncState(function);
  DrawInto(window,
    this->Accumulation,
    2,
    this->Width,
    this->Height,
    [&]
    {
      // Added to the running sums.
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
      this->PathTracer->Render();
    });
  state->vtkglBlendFuncSeparate(static_cast<unsigned int>(function[0]),
    static_cast<unsigned int>(function[1]),
    static_cast<unsigned int>(function[2]),
    static_cast<unsigned int>(function[3]));
  this->Majorants->Deactivate();
  ++this->Samples;
  return true;
}

bool vtkAVSRefinement::Show(int x,
  int y,
  int width,
  int height,
  const avs::DisplayTransform& display)
{
  vtkOpenGLRenderWindow* window = this->Window;
  if (!window || !this->AmbientHeld)
  {
    return false;
  }
  if (!this->Picture)
  {
    const std::string fs = vtkAVSShaderAssembly::RefineFragmentShader();
    this->Picture = std::make_unique<vtkOpenGLQuadHelper>(window, nullptr, fs.c_str(), "");
    if (!this->Picture->Program || !this->Picture->Program->GetCompiled())
    {
      this->Picture.reset();
      return false;
    }
  }
  vtkShaderProgram* program = this->Picture->Program;
  window->GetShaderCache()->ReadyShaderProgram(program);
  program->SetUniformi("u_ambient", Unit(this->Ambient));
  program->SetUniformi("u_sum", Unit(this->Sum));
  program->SetUniformi("u_sumSquares", Unit(this->SumSquares));
  program->SetUniformf("u_samples", static_cast<float>(this->Samples));
  vtkAVSFrameUniforms::SetDisplay(program, display);
  window->GetState()->vtkglViewport(x, y, width, height);
  this->Picture->Render();
  for (vtkTextureObject* t : { this->Ambient.Get(), this->Sum.Get(), this->SumSquares.Get() })
  {
    t->Deactivate();
  }
  vtkOpenGLStaticCheckErrorMacro("failed after showing the refined picture");
  return true;
}

bool vtkAVSRefinement::Download(avs::RefinementBuffers& buffers)
{
  vtkOpenGLRenderWindow* window = this->Window;
  if (!window || this->Samples < 1 || !this->AmbientHeld)
  {
    return false;
  }
  const std::size_t n = 4 * static_cast<std::size_t>(this->Width) * this->Height;
  buffers.Width = this->Width;
  buffers.Height = this->Height;
  buffers.Samples = this->Samples;
  buffers.Ambient.assign(n, 0.0f);
  buffers.Mean.assign(n, 0.0f);
  buffers.MeanOfSquares.assign(n, 0.0f);
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  auto read = [&](vtkOpenGLFramebufferObject* framebuffer, int attachment, std::vector<float>& to)
  {
    framebuffer->Bind(GL_READ_FRAMEBUFFER);
    glReadBuffer(static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + attachment));
    glReadPixels(0, 0, this->Width, this->Height, GL_RGBA, GL_FLOAT, to.data());
  };
  read(this->Accumulation, 0, buffers.Mean);
  read(this->Accumulation, 1, buffers.MeanOfSquares);
  read(this->AmbientTarget, 0, buffers.Ambient);
  state->PopFramebufferBindings();
  const float scale = 1.0f / static_cast<float>(this->Samples);
  for (std::size_t i = 0; i < n; ++i)
  {
    buffers.Mean[i] *= scale;
    buffers.MeanOfSquares[i] *= scale;
  }
  return glGetError() == GL_NO_ERROR;
}
