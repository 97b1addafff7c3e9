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

std::string Camera::Validate() const
{
  auto finite = [](const Vec3& v)
  { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  if (!finite(this->Position) || !finite(this->FocalPoint) || !finite(this->ViewUp) ||
    !std::isfinite(this->ViewAngle) || !std::isfinite(this->ParallelScale))
  {
    return "the camera has a non-finite position, focal point, view-up or angle";
  }
  const Vec3 forward = this->FocalPoint - this->Position;
  if (!(Length(forward) > 0.0))
  {
    return "the camera's position is its focal point";
  }
  const Vec3 right = Cross(Normalize(forward), this->ViewUp);
  if (!(Length(right) > 1e-12 * Length(this->ViewUp)) || !(Length(this->ViewUp) > 0.0))
  {
    return "the camera's view-up is zero or along its view direction";
  }
  if (this->Parallel ? !(this->ParallelScale > 0.0)
                     : !(this->ViewAngle > 0.0 && this->ViewAngle < 180.0))
  {
    return "the camera's view angle or parallel scale is out of range";
  }
  return std::string();
}

} // namespace avs
