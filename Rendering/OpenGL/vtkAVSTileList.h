/**
 * @class   vtkAVSTileList
 * @brief   a list of tiles of a 3D grid in a shader storage buffer (private)
 *
 * The tiles (Core/LightTiles.h: 8 x 8 x 1 points, packed x | y << 10 | z << 20) that a compute
 * pass runs one work group each over, as the shaders read them (avs_lightvolume_cs.glsl,
 * avs_diffusion_cs.glsl):
 *
 *     layout(std430) buffer { uint count; uint groups[3]; uint tiles[]; };
 *
 * `groups` is the indirect dispatch that covers `count` work groups (x then y, 65535 a row at
 * most). Written from the CPU (Set) or on the GPU (the diffusion's reads, vtkAVSDiffuseVolume::
 * MarkTiles, which appends to a list Reset to hold every tile of its grid).
 */
#ifndef vtkAVSTileList_h
#define vtkAVSTileList_h

#include <array>
#include <cstdint>
#include <string>
#include <vector>

class vtkAVSTileList
{
public:
  vtkAVSTileList() = default;
  vtkAVSTileList(const vtkAVSTileList&) = delete;
  vtkAVSTileList& operator=(const vtkAVSTileList&) = delete;

  /// The work groups that cover `tiles` tiles: x then y, 65535 a row at most.
  static std::array<std::uint32_t, 3> Groups(std::size_t tiles);

  /// Uploads `tiles` of the grid `dimensions` (unless they are the ones held); false with the
  /// reason when the buffer could not be written.
  bool Set(const std::array<int, 3>& dimensions,
    const std::vector<std::uint32_t>& tiles,
    std::string& error);
  /// An empty list of the grid `dimensions`, with room for all its tiles, for the GPU to append
  /// to (what Set held is forgotten).
  bool Reset(const std::array<int, 3>& dimensions, std::string& error);
  /// Whether it holds a list of the grid `dimensions`.
  bool IsOf(const std::array<int, 3>& dimensions) const
  {
    return this->Buffer && this->Dimensions == dimensions;
  }
  /// The buffer (0 before the first Set or Reset).
  unsigned int GetBuffer() const { return this->Buffer; }
  /// Binds the buffer at shader storage binding `binding` and dispatches its work groups
  /// (indirect: the count may have been written on the GPU), then unbinds it.
  void Dispatch(unsigned int binding) const;
  /// Deletes the buffer (with `context`: else the context took it with it).
  void ReleaseGraphicsResources(bool context);

private:
  bool Write(const std::array<int, 3>& dimensions,
    const std::vector<std::uint32_t>& tiles,
    std::size_t capacity,
    std::string& error);
  unsigned int Buffer = 0;
  std::size_t Capacity = 0; ///< tiles the buffer has room for
  std::array<int, 3> Dimensions{ 0, 0, 0 };
  std::vector<std::uint32_t> Held; ///< what Set wrote (empty after Reset)
  bool Uploaded = false;           ///< Held is what the buffer holds
};

#endif
