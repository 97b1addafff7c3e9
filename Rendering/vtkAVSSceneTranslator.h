/**
 * @class   vtkAVSSceneTranslator
 * @brief   translates VTK state into the VTK-free core's types (private to the module)
 *
 * A renderer's lights and a camera to core lights and camera (the image's arrays:
 * vtkAVSDataTranslator; the volume property: vtkAVSPropertyTranslator).
 */
#ifndef vtkAVSSceneTranslator_h
#define vtkAVSSceneTranslator_h

#include "Camera.h"
#include "Lights.h"

#include <string>
#include <vector>

class vtkCamera;
class vtkRenderer;

class vtkAVSSceneTranslator
{
public:
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
