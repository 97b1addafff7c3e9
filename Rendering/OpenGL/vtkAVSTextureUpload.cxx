#include "vtkAVSTextureUpload.h"

#include "vtkAVSRenderPasses.h"
#include "vtkAVSTextureMemory.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"

#include <algorithm>
#include <limits>
#include <memory>

namespace
{
// The GL internal format of `components` channels: 8 or 16 bits unsigned normalized, or 32-bit
// floats.
unsigned int InternalFormatOf(int hostType, int components)
{
  const int c = std::clamp(components, 1, 4) - 1;
  static const unsigned int u8[4] = { GL_R8, GL_RG8, GL_RGB8, GL_RGBA8 };
  static const unsigned int u16[4] = { GL_R16, GL_RG16, GL_RGB16, GL_RGBA16 };
  static const unsigned int f32[4] = { GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F };
  return hostType == VTK_UNSIGNED_CHAR ? u8[c] : (hostType == VTK_UNSIGNED_SHORT ? u16[c] : f32[c]);
}

std::string Size(const std::array<int, 3>& d)
{
  return std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]);
}
} // namespace

int vtkAVSTextureUpload::TexelFormat::HostBytes() const
{
  return this->HostType == VTK_UNSIGNED_CHAR ? 1 : (this->HostType == VTK_UNSIGNED_SHORT ? 2 : 4);
}

vtkAVSTextureUpload::TexelFormat vtkAVSTextureUpload::TexelFormat::ForScalars(int scalarType,
  int channels,
  bool floats)
{
  TexelFormat f;
  int bits = 0;
  bool isSigned = false;
  switch (scalarType)
  {
    case VTK_CHAR:
      bits = 8;
      isSigned = std::numeric_limits<char>::is_signed;
      break;
    case VTK_SIGNED_CHAR:
      bits = 8;
      isSigned = true;
      break;
    case VTK_UNSIGNED_CHAR:
      bits = 8;
      break;
    case VTK_SHORT:
      bits = 16;
      isSigned = true;
      break;
    case VTK_UNSIGNED_SHORT:
      bits = 16;
      break;
    default:
      break; // 32-bit floats
  }
  if (floats || bits == 0)
  {
    f.InternalFormat = InternalFormatOf(VTK_FLOAT, channels);
    return f;
  }
  f.HostType = bits == 8 ? VTK_UNSIGNED_CHAR : VTK_UNSIGNED_SHORT;
  f.InternalFormat = InternalFormatOf(f.HostType, channels);
  f.Scale = static_cast<float>((1 << bits) - 1);                    // 255, 65535: exact in float
  f.Shift = isSigned ? -static_cast<float>(1 << (bits - 1)) : 0.0f; // the flipped sign bit
  return f;
}

double vtkAVSTextureUpload::TexelFormat::Encode(double value) const
{
  return value - static_cast<double>(this->Shift);
}

bool vtkAVSTextureUpload::Upload(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkTextureObject>& texture,
  const std::array<int, 3>& d,
  int components,
  const TexelFormat& format,
  const SlabFill& fill,
  const std::vector<vtkTextureObject*>& held,
  std::string& error,
  const std::array<int, 2>& slices)
{
  GLint limit = 0;
  if (window)
  {
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &limit);
  }
  if (d[0] > limit || d[1] > limit || d[2] > limit)
  {
    error = "the volume (" + Size(d) +
      ") is too large for the GPU (largest 3D texture: " + std::to_string(limit) + " per axis)";
    return false;
  }
  const unsigned int internalFormat =
    format.InternalFormat ? format.InternalFormat : InternalFormatOf(VTK_FLOAT, components);
  // The budget of AVS_GPU_MEMORY_LIMIT_MB (vtkAVSTextureMemory.h), before anything is allocated.
  if (!vtkAVSTextureMemory::Admit(held, texture, d, components, internalFormat, error))
  {
    return false;
  }
  const bool keep = texture && texture->GetContext() == window &&
    texture->GetWidth() == static_cast<unsigned int>(d[0]) &&
    texture->GetHeight() == static_cast<unsigned int>(d[1]) &&
    texture->GetDepth() == static_cast<unsigned int>(d[2]) &&
    texture->GetComponents() == components &&
    texture->GetInternalFormat(format.HostType, components, false) == internalFormat;
  if (keep && !fill)
  {
    return true; // to be written on the GPU: the storage is reused
  }
  if (!keep)
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
    texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(window);
  }
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetInternalFormat(internalFormat);
  vtkAVSRenderPasses::DiscardErrors();   // the check below is of this upload alone
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1); // rows of texels are not padded
  if (!keep &&
    !texture->Create3DFromRaw(static_cast<unsigned int>(d[0]),
      static_cast<unsigned int>(d[1]),
      static_cast<unsigned int>(d[2]),
      components,
      format.HostType,
      nullptr))
  {
    error = "the GPU could not allocate a " + Size(d) + " texture (out of GPU memory?)";
    texture = nullptr;
    return false;
  }
  // A kept texture is re-filled where its texels changed; a new one everywhere.
  const int first = keep ? std::clamp(slices[0], 0, d[2]) : 0;
  const int last = keep ? std::clamp(slices[1], first, d[2]) : d[2];
  if (fill && first < last && glGetError() == GL_NO_ERROR)
  {
    const std::size_t slice =
      static_cast<std::size_t>(d[0]) * d[1] * components * format.HostBytes();
    const int slab = static_cast<int>(std::clamp<std::size_t>(SlabBytes / slice, 1, d[2]));
    // Not initialised: a fill that returns its own memory leaves these pages untouched.
    std::unique_ptr<unsigned char[]> texels(new unsigned char[slice * slab]);
    const GLenum type = format.HostType == VTK_UNSIGNED_CHAR
      ? GL_UNSIGNED_BYTE
      : (format.HostType == VTK_UNSIGNED_SHORT ? GL_UNSIGNED_SHORT : GL_FLOAT);
    const GLenum layout = texture->GetFormat(format.HostType, components, false);
    if (keep && glMemoryBarrier)
    {
      // A kept texture may have been written by a compute shader's image stores.
      glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
    texture->Activate();
    for (int z = first; z < last; z += slab)
    {
      const int z1 = std::min(last, z + slab);
      const void* source = fill(z, z1, texels.get());
      glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, z, d[0], d[1], z1 - z, layout, type, source);
    }
    texture->Deactivate();
  }
  if (glGetError() != GL_NO_ERROR)
  {
    error = "the GPU refused a 3D texture of " + Size(d) + " (out of GPU memory?)";
    texture->ReleaseGraphicsResources(window);
    texture = nullptr;
    return false;
  }
  return true;
}

bool vtkAVSTextureUpload::UploadFloats(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkTextureObject>& texture,
  const std::array<int, 3>& d,
  int components,
  const float* data,
  unsigned int internalFormat,
  const std::vector<vtkTextureObject*>& held,
  std::string& error)
{
  TexelFormat format;
  format.InternalFormat = internalFormat;
  SlabFill fill;
  if (data)
  {
    const std::size_t slice = static_cast<std::size_t>(d[0]) * d[1] * components;
    fill = [data, slice](int z0, int, void*) -> const void* { return data + slice * z0; };
  }
  return Upload(window, texture, d, components, format, fill, held, error);
}
