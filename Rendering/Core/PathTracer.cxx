#include "PathTracer.h"

#include "Extinction.h"
#include "Parallel.h"
#include "PhaseFunction.h"
#include "Random.h"
#include "SurfaceGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace avs
{

VolumeTracker::VolumeTracker(const VolumeScene& scene,
  const MajorantGrid& majorants,
  const SurfaceGrid* surfaces)
  : Scene(scene)
  , Majorants(majorants)
  , Classify(scene)
{
  this->Classify.SetSurfaceGrid(surfaces);
}

double VolumeTracker::Extinction(const Vec3& world, Vec3* color) const
{
  const Classified c = this->Classify.AtWorld(world);
  if (color)
  {
    *color = c.Color;
  }
  if (this->Scene.Clip.Clips() &&
    !this->Scene.Clip.IsInside(this->Scene.Scalars.Geometry.WorldToIndex(world)))
  {
    return 0.0; // clipped or cropped away
  }
  return c.SigmaT;
}

SurfacePoint VolumeTracker::Surface(const Vec3& world, double sigmaT, double blending) const
{
  return this->Classify.SurfaceAt(
    this->Scene.Scalars.Geometry.WorldToIndex(world), sigmaT, blending);
}

// Walks the majorant cells along the ray inside the volume box, sampling tentative collisions
// with each cell's majorant. visit(t, sigma, majorant) returns false to stop.
template<typename Visit>
void VolumeTracker::Walk(const Vec3& origin,
  const Vec3& direction,
  double maximum,
  Random& rng,
  Visit&& visit) const
{
  const GridGeometry& g = this->Scene.Scalars.Geometry;
  const Vec3 o = g.WorldToLocal(origin);
  const Vec3 d = g.WorldToLocalDirection(direction);
  double t0, t1;
  if (!IntersectVolumeBox(g, o, d, t0, t1))
  {
    return;
  }
  t0 = std::max(t0, 0.0);
  t1 = std::min(t1, maximum);
  if (!(t1 > t0))
  {
    return;
  }
  // Index space: p(t) = io + t id.
  const Vec3 io{ o.x / g.Spacing.x, o.y / g.Spacing.y, o.z / g.Spacing.z };
  const Vec3 id{ d.x / g.Spacing.x, d.y / g.Spacing.y, d.z / g.Spacing.z };
  const int B = this->Majorants.CellSize();
  const auto& cells = this->Majorants.Cells();
  double t = t0;
  while (t < t1)
  {
    // The cell around p(t) (nudged along the ray) and the distance to its exit.
    int c[3];
    double exit = t1;
    for (int a = 0; a < 3; ++a)
    {
      const double p = io[a] + (t + 1e-9 * (1.0 + t)) * id[a];
      c[a] = std::clamp(static_cast<int>(std::floor(p / B)), 0, cells[a] - 1);
      // The first and last cells reach to the box's faces (cell data's border beyond the
      // lattice takes the values at its faces, which those cells bound).
      const double lower = c[a] == 0 ? -g.Border : c[a] * B;
      const double upper = c[a] == cells[a] - 1
        ? std::max((c[a] + 1.0) * B, g.Dimensions[a] - 1 + g.Border)
        : (c[a] + 1.0) * B;
      if (id[a] > 0.0)
      {
        exit = std::min(exit, (upper - io[a]) / id[a]);
      }
      else if (id[a] < 0.0)
      {
        exit = std::min(exit, (lower - io[a]) / id[a]);
      }
    }
    exit = std::max(exit, t + 1e-12);
    const double majorant = this->Majorants.Cell(c[0], c[1], c[2]);
    if (!(majorant > 0.0))
    {
      t = exit;
      continue;
    }
    const double step = -std::log1p(-rng.Uniform()) / majorant;
    if (t + step >= exit)
    {
      t = exit; // memoryless: sample afresh in the next cell
      continue;
    }
    t += step;
    const double sigma = this->Extinction(origin + direction * t);
    if (!visit(t, sigma, majorant))
    {
      return;
    }
  }
}

double VolumeTracker::SampleCollision(const Vec3& origin,
  const Vec3& direction,
  double maximum,
  Random& rng,
  PathTracerStatistics& stats) const
{
  double hit = -1.0;
  this->Walk(origin,
    direction,
    maximum,
    rng,
    [&](double t, double sigma, double majorant)
    {
      if (rng.Uniform() * majorant < sigma)
      {
        ++stats.RealCollisions;
        hit = t;
        return false;
      }
      ++stats.NullCollisions;
      return true;
    });
  return hit;
}

double VolumeTracker::Transmittance(const Vec3& origin,
  const Vec3& direction,
  double maximum,
  Random& rng,
  PathTracerStatistics& stats) const
{
  double T = 1.0;
  this->Walk(origin,
    direction,
    maximum,
    rng,
    [&](double, double sigma, double majorant)
    {
      ++stats.NullCollisions;
      T *= std::max(0.0, 1.0 - sigma / majorant);
      if (T < 0.05)
      {
        // Russian roulette keeps the estimate unbiased.
        if (rng.Uniform() >= 0.5)
        {
          T = 0.0;
          return false;
        }
        T *= 2.0;
      }
      return T > 0.0;
    });
  return T;
}

namespace
{
struct PathContext
{
  const VolumeScene& Scene;
  const ScatteringParameters& P;
  const PathTracerSettings& S;
  const VolumeTracker& Tracker;
};

// One camera path; returns radiance and whether the primary ray collided.
Vec3 TracePath(const PathContext& c, Ray ray, Random& rng, PathTracerStatistics& stats, bool& hit)
{
  Vec3 L{ 0, 0, 0 };
  Vec3 beta{ 1, 1, 1 };
  hit = false;
  const double infinite = std::numeric_limits<double>::infinity();
  for (int bounce = 0; bounce < c.S.MaximumBounces; ++bounce)
  {
    const double t = c.Tracker.SampleCollision(ray.Origin, ray.Direction, infinite, rng, stats);
    if (t < 0.0)
    {
      break; // the environment is black; the background is composited like the mappers'
    }
    if (bounce == 0)
    {
      hit = true;
    }
    const Vec3 x = ray.Origin + ray.Direction * t;
    Vec3 color;
    const double sigma = c.Tracker.Extinction(x, &color);
    // Emission: sigma_a L_e / sigma_t at a real collision.
    L = L + Mul(beta, color) * ((1.0 - c.P.Albedo) * c.P.EmissionWeight);
    const Vec3 albedo = color * c.P.Albedo; // chromatic single-scattering albedo
    if (albedo.x <= 0.0 && albedo.y <= 0.0 && albedo.z <= 0.0)
    {
      break;
    }
    // Surfaces inside the medium: a surface event with probability P_s.
    const SurfaceShading& shading = c.P.Surface;
    const Vec3 toViewer = -ray.Direction;
    bool surface = false, facing = false;
    Vec3 normal{ 0, 0, 0 };
    if (shading.Active())
    {
      const SurfacePoint point = c.Tracker.Surface(x, sigma, shading.Blending);
      if (point.Probability > 0.0 && rng.Uniform() < point.Probability)
      {
        surface = true;
        facing = Facing(shading, point.Normal, toViewer, normal);
      }
    }
    // Next-event estimation to every light, ratio-tracked transmittance.
    for (const Light& light : c.Scene.Lights)
    {
      const Vec3 irradiance = light.FreeIrradiance(x);
      if (irradiance.x <= 0.0 && irradiance.y <= 0.0 && irradiance.z <= 0.0)
      {
        continue;
      }
      const Vec3 propagation = light.PropagationDirection(x);
      const double distance =
        light.Type == LightType::Directional ? infinite : Length(light.Position - x);
      const double T = c.Tracker.Transmittance(x, -propagation, distance, rng, stats);
      if (T > 0.0)
      {
        const double phase = HenyeyGreenstein(Dot(propagation, -ray.Direction), c.P.Anisotropy);
        if (!surface)
        {
          L = L + Mul(Mul(beta, albedo), irradiance) * (phase * T);
        }
        else
        {
          // k_a of a phase-function event plus the BRDF (0 where the surface does not face the
          // camera).
          const SurfaceReflectance r = Reflect(shading, normal, -propagation, toViewer);
          const Vec3 reflected = albedo * (shading.Ambient * phase + r.Diffuse) +
            Vec3{ r.Specular, r.Specular, r.Specular } * c.P.Albedo;
          L = L + Mul(Mul(beta, reflected), irradiance) * T;
        }
      }
    }
    // Continue: incoming light sampled from the phase function around the outgoing direction,
    // or at a surface event by the lobe chosen with the coefficients' weights.
    ray.Origin = x;
    const double u = surface ? rng.Uniform() : 0.0;
    if (!surface || u < shading.Ambient)
    {
      // (at a surface event k_a, chosen with probability k_a)
      beta = Mul(beta, albedo);
      const PhaseSample s =
        SampleHenyeyGreenstein(ray.Direction, c.P.Anisotropy, rng.Uniform(), rng.Uniform());
      ray.Direction = Normalize(s.Direction);
    }
    else if (facing && u < shading.Ambient + shading.Diffuse)
    {
      // f cos / pdf = k_d c, chosen with probability k_d.
      beta = Mul(beta, albedo);
      ray.Direction = Normalize(SampleCosine(normal, rng.Uniform(), rng.Uniform()));
    }
    else if (facing && u < shading.Ambient + shading.Diffuse + shading.Specular)
    {
      // f cos / pdf = k_s (p + 2) / (p + 1) cos, chosen with probability k_s.
      const Vec3 mirror = normal * (2.0 * Dot(normal, toViewer)) - toViewer;
      const Vec3 d = Normalize(
        SamplePhongLobe(Normalize(mirror), shading.SpecularPower, rng.Uniform(), rng.Uniform()));
      const double cosine = Dot(normal, d);
      if (!(cosine > 0.0))
      {
        break;
      }
      beta = beta *
        (c.P.Albedo * (shading.SpecularPower + 2.0) / (shading.SpecularPower + 1.0) * cosine);
      ray.Direction = d;
    }
    else
    {
      break; // absorbed
    }
    if (bounce >= c.S.RouletteDepth)
    {
      const double q = std::min(1.0, std::max({ beta.x, beta.y, beta.z }));
      if (rng.Uniform() >= q)
      {
        break;
      }
      beta = beta * (1.0 / q);
    }
  }
  ++stats.Paths;
  return L;
}
} // namespace

Image RenderPathTraced(const VolumeScene& scene,
  const ScatteringParameters& p,
  const PathTracerSettings& settings,
  const Camera& camera,
  int width,
  int height,
  PathTracerStatistics* statistics,
  const std::function<void(double)>& progress,
  Image* secondMoment)
{
  Image image;
  image.Width = std::max(0, width);
  image.Height = std::max(0, height);
  image.Pixels.assign(4 * static_cast<std::size_t>(image.Width) * image.Height, 0.0f);
  if (secondMoment)
  {
    *secondMoment = image;
  }
  if (scene.Scalars.Values.empty())
  {
    return image;
  }
  const MajorantGrid majorants(
    Classifier(scene), scene.Scalars.Geometry, settings.MajorantCellSize, &scene.Clip);
  // Surfaces read the precomputed gradient, as the renderers do (SurfaceGrid.h).
  const SurfaceGrid surfaces = p.Surface.Active() ? MakeSurfaceGrid(scene) : SurfaceGrid();
  const VolumeTracker tracker(scene, majorants, surfaces.Empty() ? nullptr : &surfaces);
  const PathContext context{ scene, p, settings, tracker };
  std::vector<double> sum(4 * static_cast<std::size_t>(image.Width) * image.Height, 0.0);
  std::vector<double> squares(secondMoment ? sum.size() : 0, 0.0);
  std::mutex statsMutex;
  PathTracerStatistics total;
  const int spp = std::max(1, settings.SamplesPerPixel);
  for (int pass = 0; pass < spp; ++pass)
  {
    ParallelFor(image.Height,
      [&](std::int64_t b, std::int64_t e)
      {
        PathTracerStatistics local;
        for (std::int64_t y = b; y < e; ++y)
        {
          for (int x = 0; x < image.Width; ++x)
          {
            const std::uint64_t pixel = static_cast<std::uint64_t>(y) * image.Width + x;
            Random rng(HashSeed(settings.Seed, pixel, static_cast<std::uint64_t>(pass)), pixel);
            const Ray ray =
              camera.GenerateRay(x + rng.Uniform(), y + rng.Uniform(), image.Width, image.Height);
            bool hit = false;
            const Vec3 L = TracePath(context, ray, rng, local, hit);
            double* s = &sum[4 * pixel];
            s[0] += L.x;
            s[1] += L.y;
            s[2] += L.z;
            s[3] += hit ? 1.0 : 0.0;
            if (secondMoment)
            {
              double* q = &squares[4 * pixel];
              q[0] += L.x * L.x;
              q[1] += L.y * L.y;
              q[2] += L.z * L.z;
              q[3] += hit ? 1.0 : 0.0;
            }
          }
        }
        std::lock_guard<std::mutex> lock(statsMutex);
        total.Paths += local.Paths;
        total.RealCollisions += local.RealCollisions;
        total.NullCollisions += local.NullCollisions;
      });
    if (progress)
    {
      progress(static_cast<double>(pass + 1) / spp);
    }
  }
  for (std::size_t i = 0; i < sum.size(); ++i)
  {
    image.Pixels[i] = static_cast<float>(sum[i] / spp);
  }
  if (secondMoment)
  {
    secondMoment->Width = image.Width;
    secondMoment->Height = image.Height;
    secondMoment->Pixels.resize(squares.size());
    for (std::size_t i = 0; i < squares.size(); ++i)
    {
      secondMoment->Pixels[i] = static_cast<float>(squares[i] / spp);
    }
  }
  if (statistics)
  {
    *statistics = total;
  }
  return image;
}

} // namespace avs
