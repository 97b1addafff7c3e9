/**
 * @class   vtkAVSSceneTranslator
 * @brief   translates VTK state into the VTK-free core's types (private to the module)
 *
 * Image data to a float grid (any scalar type, point scalars, origin, spacing, direction
 * matrix), a vtkVolumeProperty to sampled transfer functions, a renderer's lights and a camera
 * to core lights and camera. Every check of the input lives here, so all the module's classes
 * reject the same bad input with the same messages.
 */
#ifndef vtkAVSSceneTranslator_h
#define vtkAVSSceneTranslator_h

#include "Camera.h"
#include "Grid.h"
#include "Lights.h"
#include "TransferFunction.h"

#include <string>
#include <vector>

class vtkCamera;
class vtkImageData;
class vtkRenderer;
class vtkVolumeProperty;

class vtkAVSSceneTranslator
{
public:
  /// Largest number of voxels the CPU code accepts (2^30).
  static constexpr double MaximumVoxels = 1073741824.0;

  /// Checks image data and copies its active point scalars (one component) into `grid`.
  /// Returns false with a message in `error` for: no image, an empty image, no point scalars,
  /// a component count other than 1, NaN or infinite values, non-finite or non-positive
  /// spacing, a non-finite origin, a direction matrix that is not orthonormal, too many voxels,
  /// a spacing outside [1e-30, 1e30] or a box beyond +-1e30 (single precision on the GPU), an
  /// image more than 2^23 times as long as its smallest spacing (rays of over 2^24 samples).
  static bool ToGrid(vtkImageData* image, avs::Grid& grid, std::string& error);

  /// Samples the colour and scalar-opacity functions of component 0 over [lo, hi].
  static bool ToTransferFunction(vtkVolumeProperty* property,
    double lo,
    double hi,
    avs::TransferFunction& tf,
    double& unitDistance,
    std::string& error);

  /// The switched-on lights of `renderer` in world space (headlights follow the camera, camera
  /// lights are transformed by it). A renderer without lights gets a headlight, as VTK does.
  /// VTK light units (ALGORITHM.md section 1): irradiance = 4 pi x intensity x diffuse colour x
  /// `lightScale`, so that a light of intensity 1 on a thin, white, isotropic medium of albedo 1
  /// gives back the emission-absorption colour, as VTK's own scattering shader does.
  /// `followsCamera`, when given, gets for each light whether it moves with the camera
  /// (headlights and camera lights).
  static std::vector<avs::Light> ToLights(vtkRenderer* renderer,
    vtkCamera* camera,
    double lightScale = 1.0,
    std::vector<bool>* followsCamera = nullptr);

  static avs::Camera ToCamera(vtkCamera* camera);
};

#endif
