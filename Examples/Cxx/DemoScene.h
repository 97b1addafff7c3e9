// The built-in demo scene: a procedural nebula lit by a point light at its hollow centre and a
// directional light from the side, with its transfer functions and camera; or a user's file,
// framed whole and lit from outside by a key and a fill light.
#ifndef DemoScene_h
#define DemoScene_h

#include "vtkImageData.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeProperty.h"

#include <string>

struct DemoScene
{
  vtkSmartPointer<vtkImageData> Volume;
  vtkSmartPointer<vtkVolumeProperty> Property;
  vtkSmartPointer<vtkRenderer> Renderer; ///< holds the lights and the camera
};

/// The procedural nebula with n^3 voxels.
DemoScene MakeDemoScene(int n);

/// A volume read from `fileName` (.vti, .vtk, .slc, .nhdr/.nrrd, and .vdb when built with
/// OpenVDB: its default grid, level sets converted to fog volumes). Returns false and sets
/// `error` when the file cannot be read.
bool LoadDemoScene(const std::string& fileName, DemoScene& scene, std::string& error);

#endif
