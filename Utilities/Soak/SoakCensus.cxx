#include "SoakCensus.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"

#include <fstream>
#include <sstream>
#include <unistd.h>

bool GLCensus::NotAbove(const GLCensus& o) const
{
  return this->Textures <= o.Textures && this->Buffers <= o.Buffers &&
    this->Programs <= o.Programs && this->Shaders <= o.Shaders &&
    this->Framebuffers <= o.Framebuffers && this->Renderbuffers <= o.Renderbuffers &&
    this->VertexArrays <= o.VertexArrays;
}

std::string GLCensus::ToString() const
{
  std::ostringstream os;
  os << "textures " << this->Textures << ", buffers " << this->Buffers << ", programs "
     << this->Programs << ", shaders " << this->Shaders << ", framebuffers " << this->Framebuffers
     << ", renderbuffers " << this->Renderbuffers << ", vertex arrays " << this->VertexArrays;
  return os.str();
}

GLCensus CountGLObjects(vtkRenderWindow* window, unsigned int range)
{
  GLCensus c;
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    return c;
  }
  gl->MakeCurrent();
  for (GLuint name = 1; name < range; ++name)
  {
    c.Textures += glIsTexture(name) ? 1 : 0;
    c.Buffers += glIsBuffer(name) ? 1 : 0;
    c.Programs += glIsProgram(name) ? 1 : 0;
    c.Shaders += glIsShader(name) ? 1 : 0;
    c.Framebuffers += glIsFramebuffer(name) ? 1 : 0;
    c.Renderbuffers += glIsRenderbuffer(name) ? 1 : 0;
    c.VertexArrays += glIsVertexArray(name) ? 1 : 0;
  }
  glGetError(); // glIsShader and glIsProgram raise nothing, but leave the error state clean
  return c;
}

double ResidentMegabytes()
{
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0, resident = 0.0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}
