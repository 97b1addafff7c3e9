/**
 * @class   vtkAVSSurfaceTexture
 * @brief   the surfaces' precomputed gradient on the GPU (private)
 *
 * Surfaces inside the medium (ShadeOn) read the gradient of the shading component once per
 * pair of samples (avs_surface.glsl). It is made once per data and range on the host
 * (avs::SurfaceGrid: the local gradient's direction and the edge share in four bytes per voxel)
 * and kept here as an RGBA8 3D texture (u_surfaces; RGBA16 on a software rasterizer, Upload),
 * whole or one per brick of a split volume (vtkAVSBricks), filtered as the scalars are. The
 * CPU reference reads the same bytes.
 */
#ifndef vtkAVSSurfaceTexture_h
#define vtkAVSSurfaceTexture_h

#include "vtkAVSBricks.h"

#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for vtkSmartPointer<vtkTextureObject>

#include <cstdint>
#include <string>
#include <vector>

namespace avs
{
struct SurfaceGrid;
}
class vtkOpenGLRenderWindow;
class vtkWindow;

class vtkAVSSurfaceTexture
{
public:
  /// Uploads `grid` (on the scalars' lattice), whole or cropped to each of `bricks` when they
  /// split the volume; `held` are the volume's other textures for the GPU memory budget.
  /// `wide`: the bytes in 16-bit texels (RGBA16), for a software rasterizer, which filters 8-bit
  /// texels with 8-bit weights (llvmpipe: the GPU's picture 52 dB from the CPU reference's with
  /// RGBA8, 64-69 dB with RGBA16) but wider ones in floats; a GPU's filter weights are 8-bit
  /// fixed point whatever the texels (NVIDIA), so there RGBA8, 4 bytes per voxel.
  /// `scalars` (one 16-bit value per lattice point, or null): a volume not split into bricks
  /// packed with its scalars, RGBA16 whatever `wide` says, the scalar in A (the grid's edge
  /// share, which no one decodes, left out), so that the ray caster's one fetch per sample
  /// brings both (AVS_SURFACE_PACKED).
  bool Upload(vtkOpenGLRenderWindow* window,
    const avs::SurfaceGrid& grid,
    const vtkAVSBricks& bricks,
    const std::vector<vtkTextureObject*>& held,
    bool wide,
    const std::vector<std::uint16_t>* scalars,
    std::string& error);
  void ReleaseGraphicsResources(vtkWindow* window);
  bool IsUploaded() const { return this->Whole || !this->Bricks.empty(); }

  /// Binds the whole texture (or brick 0's) to u_surfaces of `program` (current).
  void Bind(unsigned int program, bool nearest);
  /// A split volume: brick `brick`'s in place of the last.
  void BindBrick(unsigned int program, int brick, bool nearest);
  void Unbind();

  /// The textures held, for the GPU memory budget.
  std::vector<vtkTextureObject*> VolumeTextures() const;

private:
  void Activate(vtkTextureObject* texture, unsigned int program, bool nearest);
  vtkSmartPointer<vtkTextureObject> Whole;
  std::vector<vtkSmartPointer<vtkTextureObject>> Bricks;
};

#endif
