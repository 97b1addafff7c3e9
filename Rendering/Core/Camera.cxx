#include "Camera.h"

#include <cmath>

namespace avs
{

Ray Camera::GenerateRay(double px, double py, int width, int height) const
{
  const Vec3 forward = Normalize(this->FocalPoint - this->Position);
  const Vec3 right = Normalize(Cross(forward, this->ViewUp));
  const Vec3 up = Cross(right, forward);
  const double aspect = static_cast<double>(width) / height;
  // Normalised device coordinates in [-1, 1].
  const double nx = 2.0 * px / width - 1.0;
  const double ny = 2.0 * py / height - 1.0;
  Ray r;
  if (this->Parallel)
  {
    const double h = this->ParallelScale;
    r.Origin = this->Position + right * (nx * h * aspect) + up * (ny * h);
    r.Direction = forward;
  }
  else
  {
    const double t = std::tan(0.5 * this->ViewAngle * Pi / 180.0);
    r.Origin = this->Position;
    r.Direction = Normalize(forward + right * (nx * t * aspect) + up * (ny * t));
  }
  return r;
}

} // namespace avs
