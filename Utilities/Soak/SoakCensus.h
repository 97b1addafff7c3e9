// What a long run must not accumulate: the GL objects of a render window's context (counted by
// name, so VTK's and the mappers' alike) and the process's resident memory.
#ifndef SoakCensus_h
#define SoakCensus_h

#include <string>

class vtkRenderWindow;

struct GLCensus
{
  int Textures = 0;
  int Buffers = 0;
  int Programs = 0;
  int Shaders = 0;
  int Framebuffers = 0;
  int Renderbuffers = 0;
  int VertexArrays = 0;

  /// Whether no kind of object is more numerous here than in `other`.
  bool NotAbove(const GLCensus& other) const;
  std::string ToString() const;
};

/// Counts the live objects of the window's context: every name below `range` that glIsTexture,
/// glIsBuffer, ... accept (Mesa and the NVIDIA driver reuse freed names, so a steady number of
/// objects keeps to a steady range of names).
GLCensus CountGLObjects(vtkRenderWindow* window, unsigned int range = 1u << 14);

/// Resident set size of the process in MiB (/proc/self/statm).
double ResidentMegabytes();

#endif
