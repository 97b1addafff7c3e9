// A pinhole or parallel camera with vtkCamera's parameters, and the rays it shoots.
#ifndef avs_Camera_h
#define avs_Camera_h

#include "Vec3.h"

#include <string>

namespace avs
{

struct Ray
{
  Vec3 Origin;
  Vec3 Direction; ///< unit
};

struct Camera
{
  Vec3 Position{ 0, 0, 1 };
  Vec3 FocalPoint{ 0, 0, 0 };
  Vec3 ViewUp{ 0, 1, 0 };
  double ViewAngle = 30.0; ///< vertical, degrees (perspective)
  bool Parallel = false;
  double ParallelScale = 1.0; ///< half the viewport height in world units (parallel)

  /// The ray through pixel (px, py) of a width x height image; (0, 0) is the lower left pixel
  /// (VTK's convention), (px + 0.5, py + 0.5) its centre when jitter is 0.5.
  Ray GenerateRay(double px, double py, int width, int height) const;

  /// Empty when rays can be generated, else what is wrong: a non-finite value, the position on
  /// the focal point (within double precision), a view-up along the view direction, a view
  /// angle outside (0, 180) degrees or a parallel scale that is not positive.
  std::string Validate() const;
};

} // namespace avs

#endif
