#include "vtkAVSSurfaceTexture.h"

#include "SurfaceGrid.h"
#include "vtkAVSTextureUpload.h"

#include "vtkAVSOpenGL.h"
#include "vtkOpenGLRenderWindow.h"

#include <algorithm>
#include <cstring>

namespace
{
// The texels of `grid` in the box at `origin` of `dimensions`, slices [z0, z1), into `out`.
void CopyBox(const avs::SurfaceGrid& grid,
  const std::array<int, 3>& origin,
  const std::array<int, 3>& dimensions,
  int z0,
  int z1,
  std::uint8_t* out)
{
  const std::array<int, 3>& n = grid.Dimensions;
  const std::size_t row = 4 * static_cast<std::size_t>(dimensions[0]);
  for (int z = z0; z < z1; ++z)
  {
    for (int y = 0; y < dimensions[1]; ++y, out += row)
    {
      const std::size_t at =
        (static_cast<std::size_t>(origin[2] + z) * n[1] + origin[1] + y) * n[0] + origin[0];
      std::memcpy(out, grid.Texels.data() + 4 * at, row);
    }
  }
}

// The whole grid's texels of slices [z0, z1) in 16-bit channels (a byte b as 257 b, the same
// normalized value), `scalars` in A, into `out` (a packed texture is never split into bricks).
void CopySlicesPacked(const avs::SurfaceGrid& grid,
  const std::vector<std::uint16_t>& scalars,
  int z0,
  int z1,
  std::uint16_t* out)
{
  const std::size_t slice = static_cast<std::size_t>(grid.Dimensions[0]) * grid.Dimensions[1];
  const std::uint8_t* in = grid.Texels.data() + 4 * slice * z0;
  for (std::size_t i = slice * z0; i < slice * z1; ++i, in += 4, out += 4)
  {
    out[0] = static_cast<std::uint16_t>(257 * in[0]);
    out[1] = static_cast<std::uint16_t>(257 * in[1]);
    out[2] = static_cast<std::uint16_t>(257 * in[2]);
    out[3] = scalars[i];
  }
}
}

bool vtkAVSSurfaceTexture::Upload(vtkOpenGLRenderWindow* window,
  const avs::SurfaceGrid& grid,
  const vtkAVSBricks& bricks,
  const std::vector<vtkTextureObject*>& callerHeld,
  bool wide,
  const std::vector<std::uint16_t>* scalars,
  std::string& error)
{
  this->ReleaseGraphicsResources(window);
  if (scalars && (bricks.IsSplit() || scalars->size() * 4 != grid.Texels.size()))
  {
    error = "the surfaces' gradient: scalars to pack that do not match it";
    return false;
  }
  vtkAVSTextureUpload::TexelFormat format;
  format.InternalFormat = wide || scalars ? GL_RGBA16 : GL_RGBA8;
  format.HostType = scalars ? VTK_UNSIGNED_SHORT : VTK_UNSIGNED_CHAR;
  format.Scale = scalars ? 65535.0f : 255.0f;
  std::vector<vtkAVSBricks::Brick> boxes;
  if (bricks.IsSplit())
  {
    boxes = bricks.GetBricks();
  }
  else
  {
    vtkAVSBricks::Brick whole;
    whole.Dimensions = grid.Dimensions;
    boxes.push_back(whole);
  }
  for (std::size_t b = 0; b < boxes.size(); ++b)
  {
    const vtkAVSBricks::Brick& box = boxes[b];
    std::vector<vtkTextureObject*> held = callerHeld;
    for (vtkTextureObject* t : this->VolumeTextures())
    {
      held.push_back(t);
    }
    vtkSmartPointer<vtkTextureObject> texture;
    const vtkAVSTextureUpload::SlabFill fill = [&grid, &box, scalars](int z0, int z1, void* texels)
    {
      if (scalars)
      {
        CopySlicesPacked(grid, *scalars, z0, z1, static_cast<std::uint16_t*>(texels));
      }
      else
      {
        CopyBox(grid, box.Origin, box.Dimensions, z0, z1, static_cast<std::uint8_t*>(texels));
      }
      return static_cast<const void*>(texels);
    };
    if (!vtkAVSTextureUpload::Upload(window, texture, box.Dimensions, 4, format, fill, held, error))
    {
      error = "the surfaces' gradient: " + error;
      this->ReleaseGraphicsResources(window);
      return false;
    }
    (bricks.IsSplit() ? this->Bricks.emplace_back() : this->Whole) = texture;
  }
  return true;
}

void vtkAVSSurfaceTexture::ReleaseGraphicsResources(vtkWindow* window)
{
  if (window)
  {
    for (vtkTextureObject* t : this->VolumeTextures())
    {
      t->ReleaseGraphicsResources(window);
    }
  }
  this->Whole = nullptr;
  this->Bricks.clear();
}

void vtkAVSSurfaceTexture::Activate(vtkTextureObject* texture, unsigned int program, bool nearest)
{
  const int filter = nearest ? vtkTextureObject::Nearest : vtkTextureObject::Linear;
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  texture->Activate();
  glUniform1i(
    glGetUniformLocation(static_cast<GLuint>(program), "u_surfaces"), texture->GetTextureUnit());
}

void vtkAVSSurfaceTexture::Bind(unsigned int program, bool nearest)
{
  vtkTextureObject* texture = this->Whole ? this->Whole.Get()
    : this->Bricks.empty()                ? nullptr
                                          : this->Bricks.front().Get();
  if (texture)
  {
    this->Activate(texture, program, nearest);
  }
}

void vtkAVSSurfaceTexture::BindBrick(unsigned int program, int brick, bool nearest)
{
  const std::size_t b = static_cast<std::size_t>(brick);
  if (b >= this->Bricks.size())
  {
    return;
  }
  this->Unbind();
  this->Activate(this->Bricks[b], program, nearest);
}

void vtkAVSSurfaceTexture::Unbind()
{
  for (vtkTextureObject* t : this->VolumeTextures())
  {
    if (t->GetTextureUnit() >= 0)
    {
      t->Deactivate();
    }
  }
}

std::vector<vtkTextureObject*> vtkAVSSurfaceTexture::VolumeTextures() const
{
  std::vector<vtkTextureObject*> out;
  if (this->Whole)
  {
    out.push_back(this->Whole);
  }
  for (const auto& t : this->Bricks)
  {
    out.push_back(t);
  }
  return out;
}
