/**
 * @class   vtkAVSPropertyTranslator
 * @brief   a vtkVolumeProperty as the core classifies with it (private)
 *
 * Samples the property's functions over the data's component ranges into the core's tables
 * (1024 entries) and fills the rest of the classification (Core/Medium.h) as VTK's mapper reads
 * the property: one component; dependent components (IndependentComponentsOff: 2 components
 * take their colour from component 0 through colour function 0 and their opacity from component
 * 1 through opacity function 0; 4 components take RGB straight from components 0-2 (as VTK's
 * texture holds them: unsigned char / 255, unsigned short / 65535, signed char / 127, short /
 * 32767, float as they are, other types mapped over their range; clamped to [0, 1]) and their
 * opacity from component 3 through opacity function 0; the unit distance is that of the opacity
 * component, as in VTK); independent components (each its own functions, unit distance and
 * component weight); gradient opacity (SetGradientOpacity, DisableGradientOpacity) over a
 * quarter of the component's range, as VTK's table; the interpolation type; the label functions
 * of a label-map mask (SetLabelColor, SetLabelScalarOpacity). ToSurface reads the shading
 * (ShadeOn and the Phong coefficients) for surfaces inside the medium.
 */
#ifndef vtkAVSPropertyTranslator_h
#define vtkAVSPropertyTranslator_h

#include "ReferenceRenderer.h"

#include <array>
#include <string>
#include <vector>

class vtkRenderer;
class vtkVolumeProperty;

class vtkAVSPropertyTranslator
{
public:
  /// Table entries per function.
  static constexpr int TableSize = 1024;

  /// Fills scene.Transfer, scene.UnitDistance and the functions, weights, mode, interpolation
  /// and labels of scene.Medium (its grids are left as they are; Medium.Components is resized
  /// to ranges.size() - 1) for data of the given component ranges and VTK scalar type. `labelMap`
  /// says whether a label-map mask is used. Returns false with a message for: no property, a 2D
  /// transfer function, 3 dependent components, a unit distance that is not finite and positive, a
  /// label map on data of several components. `warning` is set for what is not honoured (a
  /// label's gradient opacity).
  static bool ToMedium(vtkVolumeProperty* property,
    const std::vector<std::array<double, 2>>& ranges,
    int scalarType,
    bool labelMap,
    avs::VolumeScene& scene,
    std::string& error,
    std::string& warning);

  /// Surfaces inside the medium (avs/SurfaceShading.h): component 0's ShadeOn and Phong
  /// coefficients (as vtkGPUVolumeRayCastMapper reads them for one component), the blending
  /// (VolumetricScatteringBlending) and the renderer's TwoSidedLighting (on without a renderer).
  static avs::SurfaceShading ToSurface(vtkVolumeProperty* property,
    double blending,
    vtkRenderer* renderer);

  /// Samples the colour and scalar-opacity functions of component `index` over [lo, hi] (an
  /// empty range is widened to [lo, lo + 1]).
  static bool ToTransferFunction(vtkVolumeProperty* property,
    int index,
    double lo,
    double hi,
    avs::TransferFunction& tf,
    std::string& error);
};

#endif
