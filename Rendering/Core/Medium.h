// What a volume's voxels are beyond one linearly interpolated component with its colour and
// opacity functions (ALGORITHM.md section 1, VTK's conventions): more components, dependent or
// independent; gradient opacity; nearest interpolation; voxels that are NaN (empty space); a
// binary or label-map mask. VolumeScene::Scalars, Transfer and UnitDistance are component 0;
// this struct holds the rest. Classifier (Classifier.h) turns it into sigma_t and colour for
// every CPU renderer, avs_classify.glsl for the GPU, the same way.
#ifndef avs_Medium_h
#define avs_Medium_h

#include "Grid.h"
#include "TransferFunction.h"

#include <vector>

namespace avs
{

/// How the components make colour and opacity (vtkVolumeProperty::IndependentComponents).
enum class ComponentMode
{
  Single,                ///< one component: its colour and opacity functions
  DependentColorOpacity, ///< 2 components: colour from 0's colour function, opacity from 1
  DependentRGBA,         ///< 4 components: RGB from 0-2 (over their ranges), opacity from 3
  Independent            ///< 1-4 components, each its own medium; the extinctions add
};

enum class Interpolation
{
  Linear, ///< trilinear, then classified (VTK_LINEAR_INTERPOLATION)
  Nearest ///< the nearest voxel's value (VTK_NEAREST_INTERPOLATION)
};

enum class MaskType
{
  None,
  Binary,  ///< voxels whose mask value is <= 0 are empty
  LabelMap ///< voxels of label L >= 1 take label L's functions, blended by MaskBlendFactor
};

/// A component beyond the first.
struct MediumComponent
{
  Grid Values;                      ///< on the scalars' grid (0 at NaN voxels, see Validity)
  TransferFunction Transfer;        ///< colour and opacity over the component's range
  double UnitDistance = 1.0;        ///< its scalar-opacity unit distance
  double Weight = 1.0;              ///< independent components: its weight in [0, 1]
  TransferFunction GradientOpacity; ///< empty Opacity: none (see MediumOptions)
};

struct MediumOptions
{
  ComponentMode Mode = ComponentMode::Single;
  Interpolation Sampling = Interpolation::Linear;
  /// Component 0's weight (independent components).
  double Weight = 1.0;
  /// Component 0's gradient opacity: a table over gradient magnitudes [Minimum = 0, Maximum =
  /// a quarter of the component's scalar range] (VTK's table), clamped beyond; empty Opacity:
  /// none. It multiplies the component's extinction. The gradient is VTK's: central differences
  /// of the sampled component at one voxel on either side along each index axis,
  /// g_a = (s(x + e_a) - s(x - e_a)) / 2 * (mean spacing / spacing_a). In the dependent modes
  /// the opacity component's gradient opacity (its MediumComponent's) is the one used.
  TransferFunction GradientOpacity;
  std::vector<MediumComponent> Components; ///< components 1-3
  /// Empty when every voxel is finite. Else 1 at finite voxels and 0 at voxels with a NaN, whose
  /// components all hold 0: a sample is the interpolated components divided by the interpolated
  /// validity, and its extinction is multiplied by the interpolated validity, so NaN voxels are
  /// empty space and the medium fades to them over one voxel.
  Grid Validity;
  MaskType Mask = MaskType::None;
  Grid MaskValues; ///< on the scalars' grid, read at the nearest voxel
  /// Label L's colour and opacity over component 0's range at index L - 1; labels without an
  /// entry take component 0's functions (as VTK's mapper does).
  std::vector<TransferFunction> Labels;
  /// Label maps: 0 ignores the labels, 1 (default) takes the label's functions, between them
  /// the label's medium and the unlabelled one are mixed: sigma_t = (1 - b) sigma_0 + b sigma_L,
  /// the colour their extinction-weighted mean.
  double MaskBlendFactor = 1.0;

  int NumberOfComponents() const { return 1 + static_cast<int>(this->Components.size()); }
  bool HasGradientOpacity() const
  {
    if (!this->GradientOpacity.Opacity.empty())
    {
      return true;
    }
    for (const MediumComponent& c : this->Components)
    {
      if (!c.GradientOpacity.Opacity.empty())
      {
        return true;
      }
    }
    return false;
  }
};

} // namespace avs

#endif
