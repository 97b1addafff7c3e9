/**
 * @class   vtkAVSTextureUpload
 * @brief   every 3D texture of the ray caster is allocated and filled here (private)
 *
 * One place for the 3D uploads of vtkAVSVolumeTextures and vtkAVSClassification: the check
 * against the GPU memory budget (vtkAVSTextureMemory) before anything is allocated, the
 * allocation, and the texels written slab by slab along z (glTexSubImage3D of at most
 * SlabBytes each), each slab converted into the texel type while uploading, so that no host
 * copy of the whole volume in the texture's type is made.
 *
 * The scalars' texel format (TexelFormat::ForScalars) follows the array's type, as
 * vtkGPUVolumeRayCastMapper uploads it: 8- and 16-bit integers in their own normalized formats
 * (R8, R16 and their RG/RGB/RGBA forms), everything else (32-bit integers, float, double, and
 * any volume with NaN voxels, whose validity rides beside the components) as 32-bit floats.
 * A normalized texel u in [0, 1] is the data value u * Scale + Shift, which avs_classify.glsl
 * applies (u_valueScale, u_valueShift) where it reads the texel. Signed types go in unsigned
 * normalized formats with the sign bit flipped (value + 2^(b-1)), not in the SNORM formats:
 * OpenGL 4.5 (section 2.3.5.1) converts a signed normalized c to max(c / (2^(b-1) - 1), -1),
 * so the type's minimum and the value above it both become -1 and the texture could not
 * interpolate them as the CPU reference does; an offset UNORM texel keeps every value of the
 * type apart, in the same bytes.
 */
#ifndef vtkAVSTextureUpload_h
#define vtkAVSTextureUpload_h

#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for vtkSmartPointer<vtkTextureObject>
#include "vtkType.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;

class vtkAVSTextureUpload
{
public:
  /// The largest slab uploaded at once (bytes of texels on the host).
  static constexpr std::size_t SlabBytes = 16u << 20;

  /// How a texture stores its channels.
  struct TexelFormat
  {
    /// GL internal format (0: 32-bit floats of the channel count).
    unsigned int InternalFormat = 0;
    /// VTK type of the texels on the host: VTK_FLOAT, VTK_UNSIGNED_CHAR or VTK_UNSIGNED_SHORT.
    int HostType = VTK_FLOAT;
    /// A texel's normalized value u is the data value u * Scale + Shift (1 and 0 for floats).
    float Scale = 1.0f;
    float Shift = 0.0f;

    /// Bytes of one channel on the host.
    int HostBytes() const;
    bool IsNormalized() const { return this->HostType != VTK_FLOAT; }
    /// The texels of a scalar array of VTK type `scalarType` with `channels` channels;
    /// `floats` forces 32-bit floats (NaN voxels, whose validity goes with the components).
    static TexelFormat ForScalars(int scalarType, int channels, bool floats);
    /// The normalized integer that stores data value `value` (an integer of the type).
    double Encode(double value) const;
  };

  /// Writes the slices [z0, z1) into `texels` (host texels of the format's HostType,
  /// `components` per voxel, x fastest) and returns `texels`, or returns where those texels
  /// already lie in that layout (nothing written).
  using SlabFill = std::function<const void*(int z0, int z1, void* texels)>;

  /// Every slice of a texture.
  static constexpr std::array<int, 2> AllSlices{ 0, 1 << 30 };

  /// Makes `texture` a 3D texture of `dimensions` with `components` channels in `format`,
  /// clamped to the edge, linear, and fills it slab by slab through `fill` (empty: left
  /// undefined, to be written on the GPU). Where it already is one of that size, channels and
  /// format its storage is kept and only the slices [slices[0], slices[1]) are written (the
  /// others keep their texels: what did not change); otherwise it is allocated anew and every
  /// slice is written. `held` are the volume's textures for the memory budget (`texture` among
  /// them or not). Returns false and says why in `error` when the 3D-texture limit, the budget
  /// or the GPU refuses; `texture` is then null.
  static bool Upload(vtkOpenGLRenderWindow* window,
    vtkSmartPointer<vtkTextureObject>& texture,
    const std::array<int, 3>& dimensions,
    int components,
    const TexelFormat& format,
    const SlabFill& fill,
    const std::vector<vtkTextureObject*>& held,
    std::string& error,
    const std::array<int, 2>& slices = AllSlices);

  /// The same for `components` floats per voxel at `data` (null: undefined), in the GL internal
  /// format `internalFormat` (0: 32-bit floats), uploaded slab by slab from `data` itself.
  static bool UploadFloats(vtkOpenGLRenderWindow* window,
    vtkSmartPointer<vtkTextureObject>& texture,
    const std::array<int, 3>& dimensions,
    int components,
    const float* data,
    unsigned int internalFormat,
    const std::vector<vtkTextureObject*>& held,
    std::string& error);
};

#endif
