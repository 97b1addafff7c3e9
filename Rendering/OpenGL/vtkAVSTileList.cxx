#include "vtkAVSTileList.h"

#include "LightTiles.h"
#include "vtkAVSOpenGL.h"
#include "vtkAVSRenderPasses.h"

#include <algorithm>

std::array<std::uint32_t, 3> vtkAVSTileList::Groups(std::size_t tiles)
{
  const std::size_t row = 65535;
  return { static_cast<std::uint32_t>(std::min(tiles, row)),
    static_cast<std::uint32_t>(tiles == 0 ? 0 : (tiles + row - 1) / row),
    1u };
}

bool vtkAVSTileList::Set(const std::array<int, 3>& dimensions,
  const std::vector<std::uint32_t>& tiles,
  std::string& error)
{
  if (this->Uploaded && dimensions == this->Dimensions && tiles == this->Held)
  {
    return true;
  }
  if (!this->Write(dimensions, tiles, tiles.size(), error))
  {
    return false;
  }
  this->Held = tiles;
  this->Uploaded = true;
  return true;
}

bool vtkAVSTileList::Reset(const std::array<int, 3>& dimensions, std::string& error)
{
  this->Held.clear();
  this->Uploaded = false;
  return this->Write(dimensions, {}, avs::NumberOfLightTiles(dimensions), error);
}

bool vtkAVSTileList::Write(const std::array<int, 3>& dimensions,
  const std::vector<std::uint32_t>& tiles,
  std::size_t capacity,
  std::string& error)
{
  vtkAVSRenderPasses::DiscardErrors();
  // (A shader may have written the header that is rewritten below.)
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (!this->Buffer)
  {
    glGenBuffers(1, &this->Buffer);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffer);
  // (At least one tile's room: a buffer of no bytes is not one a shader can be given.)
  capacity = std::max<std::size_t>(capacity, 1);
  const std::array<std::uint32_t, 3> groups = Groups(tiles.size());
  const std::uint32_t header[4] = {
    static_cast<std::uint32_t>(tiles.size()), groups[0], groups[1], groups[2]
  };
  if (capacity != this->Capacity)
  {
    glBufferData(GL_SHADER_STORAGE_BUFFER,
      static_cast<GLsizeiptr>((4 + capacity) * sizeof(std::uint32_t)),
      nullptr,
      GL_DYNAMIC_DRAW);
  }
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(header), header);
  if (!tiles.empty())
  {
    glBufferSubData(GL_SHADER_STORAGE_BUFFER,
      sizeof(header),
      static_cast<GLsizeiptr>(tiles.size() * sizeof(std::uint32_t)),
      tiles.data());
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  if (const GLenum status = glGetError())
  {
    error = "a list of tiles could not be uploaded (GL error " + std::to_string(status) + ")";
    this->Uploaded = false;
    this->Capacity = 0;
    this->Dimensions = { 0, 0, 0 };
    return false;
  }
  this->Capacity = capacity;
  this->Dimensions = dimensions;
  return true;
}

void vtkAVSTileList::Dispatch(unsigned int binding) const
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, this->Buffer);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, this->Buffer);
  glDispatchComputeIndirect(static_cast<GLintptr>(sizeof(std::uint32_t)));
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
}

void vtkAVSTileList::ReleaseGraphicsResources(bool context)
{
  if (this->Buffer && context)
  {
    glDeleteBuffers(1, &this->Buffer);
  }
  this->Buffer = 0;
  this->Capacity = 0;
  this->Held.clear();
  this->Uploaded = false;
  this->Dimensions = { 0, 0, 0 };
}
