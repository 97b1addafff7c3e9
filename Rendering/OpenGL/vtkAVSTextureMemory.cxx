#include "vtkAVSTextureMemory.h"

#include "vtkAVSOpenGL.h"
#include "vtkTextureObject.h"
#include "vtkType.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
double BytesPerComponent(unsigned int internalFormat)
{
  switch (internalFormat)
  {
    case GL_R8:
    case GL_RG8:
    case GL_RGB8:
    case GL_RGBA8:
      return 1.0;
    case GL_R16:
    case GL_RG16:
    case GL_RGB16:
    case GL_RGBA16:
    case GL_R16F:
    case GL_RG16F:
    case GL_RGB16F:
    case GL_RGBA16F:
      return 2.0;
    default:
      return 4.0; // the ray caster's other volume textures are 32-bit floats
  }
}

std::string Mebibytes(double bytes)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f MiB", bytes / (1024.0 * 1024.0));
  return text;
}
} // namespace

namespace
{
double MapperBudget = 0.0; // ScopedBudget's
}

vtkAVSTextureMemory::ScopedBudget::ScopedBudget(double bytes)
  : Previous(MapperBudget)
{
  MapperBudget = bytes > 0.0 ? bytes : 0.0;
}

vtkAVSTextureMemory::ScopedBudget::~ScopedBudget()
{
  MapperBudget = this->Previous;
}

double vtkAVSTextureMemory::LimitBytes()
{
  const char* text = std::getenv("AVS_GPU_MEMORY_LIMIT_MB");
  const double mebibytes = text ? std::atof(text) : 0.0;
  const double environment = mebibytes > 0.0 ? mebibytes * 1024.0 * 1024.0 : 0.0;
  if (environment > 0.0 && MapperBudget > 0.0)
  {
    return std::min(environment, MapperBudget);
  }
  return environment > 0.0 ? environment : MapperBudget;
}

double vtkAVSTextureMemory::Bytes(const std::array<int, 3>& d,
  int components,
  unsigned int internalFormat)
{
  return static_cast<double>(d[0]) * d[1] * d[2] * components * BytesPerComponent(internalFormat);
}

double vtkAVSTextureMemory::Bytes(vtkTextureObject* t)
{
  if (!t || !t->GetHandle())
  {
    return 0.0;
  }
  const std::array<int, 3> d = { static_cast<int>(t->GetWidth()),
    static_cast<int>(t->GetHeight()),
    static_cast<int>(t->GetDepth()) };
  return Bytes(d, t->GetComponents(), t->GetInternalFormat(VTK_FLOAT, t->GetComponents(), false));
}

bool vtkAVSTextureMemory::Admit(const std::vector<vtkTextureObject*>& held,
  const vtkTextureObject* replaced,
  const std::array<int, 3>& d,
  int components,
  unsigned int internalFormat,
  std::string& error)
{
  const double limit = LimitBytes();
  if (limit <= 0.0)
  {
    return true;
  }
  double kept = 0.0;
  for (vtkTextureObject* t : held)
  {
    kept += t == replaced ? 0.0 : Bytes(t);
  }
  const double needed = Bytes(d, components, internalFormat);
  if (kept + needed <= limit)
  {
    return true;
  }
  error = "out of GPU memory: a " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " +
    std::to_string(d[2]) + " texture of " + std::to_string(components) + " channel" +
    (components > 1 ? "s" : "") + " needs " + Mebibytes(needed) + " beside the " + Mebibytes(kept) +
    " this volume holds, more than the " + Mebibytes(limit) +
    " allowed (the GPU memory budget: SetMaximumGPUMemory, AVS_GPU_MEMORY_LIMIT_MB)";
  return false;
}

double vtkAVSTextureMemory::ReportedBytes()
{
  // Both report kibibytes; asked only where the extension is there (an unknown enum would be an
  // error; whatever the query left is cleared below).
  auto supported = [](const char* name)
  {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
    {
      const char* e = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
      if (e && std::string(e) == name)
      {
        return true;
      }
    }
    return false;
  };
  // A device with unified memory (an integrated GPU; Mesa's llvmpipe from Mesa 25 on) reports
  // almost no dedicated memory (a few KiB) through NVX and none free through ATI: there the
  // total available memory counts, and a report below 64 MiB is taken as no report at all.
  constexpr GLint plausibleKiB = 64 * 1024;
  GLint kib[4] = { 0, 0, 0, 0 };
  if (supported("GL_NVX_gpu_memory_info"))
  {
    glGetIntegerv(0x9047, kib); // GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX
    if (kib[0] < plausibleKiB)
    {
      glGetIntegerv(0x9048, kib); // GPU_MEMORY_INFO_TOTAL_AVAILABLE_MEMORY_NVX
    }
  }
  if (kib[0] < plausibleKiB && supported("GL_ATI_meminfo"))
  {
    glGetIntegerv(0x87FC, kib); // TEXTURE_FREE_MEMORY_ATI: total free, largest block, ...
  }
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i)
  {
  }
  return kib[0] >= plausibleKiB ? kib[0] * 1024.0 : 0.0;
}
