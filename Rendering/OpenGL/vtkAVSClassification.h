/**
 * @class   vtkAVSClassification
 * @brief   the GL side of the classification (private): tables, mask, validity, uniforms
 *
 * What avs_classify.glsl needs beside the volume texture, for the ray caster and the
 * averaged-extinction pass alike: its compile-time choices (Layout::Defines), the table rows
 * (components' colour and opacity, gradient opacities, label functions) as the layers of one
 * RGBA16F 1D array texture, the mask (nearest) and, for 4 components with NaN voxels, the validity
 * in a texture of its own; and their uniforms. The CPU twin is Rendering/Core/Classifier.cxx.
 */
#ifndef vtkAVSClassification_h
#define vtkAVSClassification_h

#include "ReferenceRenderer.h"
#include "vtkAVSBricks.h"

#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for the textures VolumeTextures returns

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkAVSClassification
{
public:
  /// The compile-time choices for a scene, and how the volume texture is laid out.
  struct Layout
  {
    int Components = 1;
    int Mode = 0;     ///< AVS_MODE
    int Validity = 0; ///< AVS_VALIDITY: 0 none, 1 channel after the components, 2 own texture
    int Gradient = 0; ///< AVS_GRADIENT bit mask
    int Mask = 0;     ///< AVS_MASK
    bool Nearest = false;
    /// Channels of the volume texture: the components, and the validity when it is with them.
    int ScalarChannels() const { return this->Components + (this->Validity == 1 ? 1 : 0); }
    /// Whether the volume texture is one channel of scalars that the classification reads alone
    /// (no validity, no gradient opacity): what may ride beside the surfaces' gradient.
    bool ScalarAlone() const
    {
      return this->ScalarChannels() == 1 && this->Validity == 0 && this->Gradient == 0;
    }
    std::string Defines() const;
    bool operator==(const Layout& o) const
    {
      return this->Components == o.Components && this->Mode == o.Mode &&
        this->Validity == o.Validity && this->Gradient == o.Gradient && this->Mask == o.Mask &&
        this->Nearest == o.Nearest;
    }
  };
  static Layout LayoutOf(const avs::VolumeScene& scene);

  void SetWindow(vtkOpenGLRenderWindow* window) { this->Window = window; }
  void ReleaseGraphicsResources(vtkWindow* window);

  /// The tables and uniforms of `scene` (its functions and geometry), the mask and the separate
  /// validity where the layout has them; those two go into the GPU memory budget
  /// (vtkAVSTextureMemory) beside `held`, the caller's volume textures. A split volume's
  /// (`bricks`) mask and validity are split the same way, one texture per brick.
  bool Upload(const avs::VolumeScene& scene,
    const std::vector<vtkTextureObject*>& held,
    const vtkAVSBricks& bricks,
    std::string& error);

  /// The 3D textures it holds (the mask and the separate validity, whole or per brick; null
  /// where there is none), for the GPU memory budget.
  std::vector<vtkTextureObject*> VolumeTextures() const;

  /// How the volume texture's components map back to data values: texel * scale + shift
  /// (vtkAVSTextureUpload::TexelFormat; 1 and 0 for float texels), after Upload.
  void SetValueMap(float scale, float shift);
  /// Binds the textures and sets the uniforms on the GL program `program` (current).
  void Bind(unsigned int program);
  void Unbind();
  /// A split volume: binds brick `brick`'s mask and validity in place of the last ones (after
  /// Bind, the same program current).
  void BindBrick(unsigned int program, int brick);

  const Layout& GetLayout() const { return this->Current; }
  /// Whether Upload has run since the last release.
  bool IsUploaded() const { return this->Transfer != nullptr; }

private:
  void ReleaseTransfer();
  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned int TransferHandle = 0; ///< the 1D array texture's GL name (ours to delete)
  vtkSmartPointer<vtkTextureObject> Transfer, Mask, Validity;
  /// A split volume's mask and validity, one texture per brick (empty otherwise).
  std::vector<vtkSmartPointer<vtkTextureObject>> MaskBricks, ValidityBricks;
  void ReleaseBricks();
  Layout Current;
  float TransferSize[2] = { 1, 1 };
  float RowMap[16] = {};  // value -> x texture coordinate per row
  float RowY[8] = {};     // y texture coordinate per row
  float ColorMap[6] = {}; // dependent RGBA: value -> [0, 1]
  float UnitDistance[4] = { 1, 1, 1, 1 };
  float Weight[4] = { 1, 1, 1, 1 };
  float GradientScale[3] = { 0.5f, 0.5f, 0.5f };
  float VoxelStep[3] = { 1, 1, 1 };
  float ValueScale[4] = { 1, 1, 1, 1 }; // u_valueScale
  float ValueShift[4] = { 0, 0, 0, 0 }; // u_valueShift
  float MaskBlend = 1.0f;
  float Labels = 0.0f;
};

#endif
