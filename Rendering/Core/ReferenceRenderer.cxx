#include "ReferenceRenderer.h"

#include "AmbientOcclusion.h"
#include "AveragedExtinction.h"
#include "Classifier.h"
#include "DiffuseFluence.h"
#include "Extinction.h"
#include "LightVolume.h"
#include "Parallel.h"
#include "PhaseFunction.h"
#include "SurfaceGrid.h"
#include "SurfaceShading.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

namespace avs
{

Vec3 Image::Composited(int x, int y, const Vec3& background) const
{
  const float* p = this->At(x, y);
  const double t = 1.0 - p[3];
  return { p[0] + t * background.x, p[1] + t * background.y, p[2] + t * background.z };
}

Grid ExtinctionGrid(const VolumeScene& scene)
{
  Grid out(scene.Scalars.Geometry);
  const Classifier classifier(scene);
  const auto& n = out.Geometry.Dimensions;
  ParallelFor(n[2],
    [&](std::int64_t b, std::int64_t e)
    {
      for (std::int64_t k = b; k < e; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i)
          {
            out.At(i, j, static_cast<int>(k)) =
              static_cast<float>(classifier.AtVoxel(i, j, static_cast<int>(k)).SigmaT);
          }
    });
  ClearOutside(scene.Clip, out);
  return out;
}

namespace
{
// A grid over the data's lattice (light volumes, averaged extinction, occlusion) at a local point
// of the volume, clamped into its lattice as the GPU's textures clamp to the edge: cell data's
// border reaches half a cell beyond the lattice.
inline double SampleLocalClamped(const Grid& g, const Vec3& local)
{
  const Vec3& s = g.Geometry.Spacing;
  return g.SampleClamped({ local.x / s.x, local.y / s.y, local.z / s.z });
}
} // namespace

std::vector<Grid> ComputeDiffuse(const Grid& averaged,
  const std::vector<Light>& lights,
  const std::vector<Grid>& lightVolumes,
  const ScatteringParameters& p,
  double* residual)
{
  DiffusionSettings settings;
  settings.Albedo = p.Albedo;
  settings.Anisotropy = p.Anisotropy;
  settings.Iterations = p.DiffusionIterations;
  settings.CoarseIterations = p.DiffusionCoarseIterations;
  settings.TransportLengthLimit = TransportLengthLimitInRadii * p.AmbientRadius;
  settings.AmbientRadius = p.AmbientRadius;
  const GridGeometry target =
    DiffusionGeometry(averaged.Geometry, p.DiffusionVolumeMaximumDimension);
  const std::array<Grid, 3> phi =
    ComputeDiffusion(averaged, lights, lightVolumes, target, settings, residual);
  // Onto the light grid, where the rays read it with the averaged extinction (the GPU packs
  // both into one texture).
  return { ResampleTrilinear(phi[0], averaged.Geometry),
    ResampleTrilinear(phi[1], averaged.Geometry),
    ResampleTrilinear(phi[2], averaged.Geometry) };
}

bool Precompute(const VolumeScene& scene,
  const ScatteringParameters& p,
  const ScatteringTable* table,
  RenderMode mode,
  PrecomputedVolumes& out,
  std::string* error,
  const std::function<void(double)>& progress)
{
  if (scene.Scalars.Values.empty() ||
    scene.Scalars.Values.size() != scene.Scalars.Geometry.NumberOfPoints())
  {
    if (error)
    {
      *error = "the volume has no scalars";
    }
    return false;
  }
  if (mode == RenderMode::AmbientScattering && !table)
  {
    if (error)
    {
      *error = "ambient scattering needs a scattering table";
    }
    return false;
  }
  auto report = [&](double v)
  {
    if (progress)
    {
      progress(v);
    }
  };
  out = PrecomputedVolumes();
  out.Extinction = ExtinctionGrid(scene);
  report(0.1);
  const GridGeometry& geometry = scene.Scalars.Geometry;
  if (mode == RenderMode::AmbientOcclusion)
  {
    out.Occlusion = ComputeAmbientOcclusion(out.Extinction,
      geometry.Capped(p.OcclusionVolumeMaximumDimension),
      p.OcclusionRadius,
      p.NumberOfDirections,
      0.0,
      nullptr,
      [&](double v) { report(0.1 + 0.9 * v); });
  }
  else if (mode == RenderMode::AmbientScattering)
  {
    out.Slice = table->Slice(p.Anisotropy, p.Albedo);
    // The averaged extinction lives on the light volumes' grid, as in the GPU mappers.
    const GridGeometry lightGeometry = geometry.Capped(p.LightVolumeMaximumDimension);
    out.Averaged = AverageExtinctionOn(out.Extinction, p.AmbientRadius, lightGeometry);
    report(0.2);
    const std::size_t n = scene.Lights.size();
    for (std::size_t j = 0; j < n; ++j)
    {
      out.LightVolumes.push_back(ComputeLightVolume(
        out.Averaged,
        lightGeometry,
        scene.Lights[j],
        out.Slice,
        p.AmbientRadius,
        nullptr,
        [&](double v) { report(0.2 + 0.7 * (j + v) / n); },
        TubeLawFor(p.Model == ScatteringModel::Extended, scene.Lights[j].Type)));
    }
    if (p.Model == ScatteringModel::Extended)
    {
      out.Diffuse = ComputeDiffuse(out.Averaged, scene.Lights, out.LightVolumes, p);
    }
  }
  report(1.0);
  return true;
}

namespace
{

// The most samples one ray takes.
constexpr int MaximumRaySamples = 1 << 26;

// A local-frame point or direction in index units (component-wise division by the spacing).
Vec3 InIndexUnits(const Vec3& local, const Vec3& spacing)
{
  return { local.x / spacing.x, local.y / spacing.y, local.z / spacing.z };
}

// One ray, front to back. Returns premultiplied L and alpha.
void CastRay(const VolumeScene& scene,
  const Classifier& classifier,
  const ScatteringParameters& p,
  const PrecomputedVolumes& v,
  RenderMode mode,
  const Ray& ray,
  float* pixel)
{
  pixel[0] = pixel[1] = pixel[2] = pixel[3] = 0.0f;
  const GridGeometry& geometry = scene.Scalars.Geometry;
  const Vec3 o = geometry.WorldToLocal(ray.Origin);
  const Vec3 d = geometry.WorldToLocalDirection(ray.Direction);
  double t0, t1;
  if (!IntersectVolumeBox(geometry, o, d, t0, t1) || t1 <= 0.0)
  {
    return;
  }
  t0 = std::max(t0, 0.0); // camera inside the volume
  // Clipping planes and the kept cropping regions' box shorten the ray (as on the GPU).
  const Vec3& spacing = geometry.Spacing;
  if (scene.Clip.Clips() &&
    !scene.Clip.ClipRay(InIndexUnits(o, spacing), InIndexUnits(d, spacing), t0, t1))
  {
    return;
  }
  // Counted in double and capped before the int cast (undefined beyond int's range); the
  // translator refuses images whose rays would need anywhere near the cap.
  const double steps = std::ceil((t1 - t0) / p.SampleDistance - 1e-9);
  const int n =
    steps >= 1.0 ? static_cast<int>(std::min(steps, static_cast<double>(MaximumRaySamples))) : 1;
  const double dt = (t1 - t0) / n;
  // Ambient scattering's look-ahead r = (lag + fraction) steps; beyond the ray's n steps it
  // changes nothing, so it is capped there.
  double lagSteps = p.AmbientRadius / dt;
  if (!(lagSteps < n))
  {
    lagSteps = n;
  }
  const int lag = static_cast<int>(std::floor(lagSteps));
  const double fraction = lagSteps - lag;
  // sigma_t and colour at a local point: classification after interpolation, as on the GPU.
  auto classify = [&](const Vec3& x, double& sigmaT, Vec3& color)
  {
    const Classified c = classifier.AtLocal(x);
    sigmaT = c.SigmaT;
    color = c.Color;
    if (scene.Clip.Clips() && !scene.Clip.IsInside(InIndexUnits(x, spacing)))
    {
      sigmaT = 0.0; // clipped or cropped away
    }
  };
  // Where sample s reads its lights: with groups of G samples (G = 2 or 4,
  // ScatteringParameters::LightGroup on the light grid) the midpoint of the samples G m to
  // G m + G - 1 that hold s, for all of them (beyond the ray's end where its last group is not
  // whole), else the sample itself; as the GPU reads them.
  const int group = mode == RenderMode::AmbientScattering
    ? ScatteringParameters::LightGroup(p.SampleDistance, v.Averaged.Geometry)
    : 1;
  const bool pairs = group > 1;
  auto lightPoint = [&](int s)
  {
    const double at = (s - s % group) + 0.5 * group;
    return o + d * (t0 + at * dt);
  };
  // Surfaces inside the medium (SurfaceShading.h): sample s with extinction sigma as a surface
  // (P_s, world normal), the gradient read at the sample itself, or with groups the mean of the
  // gradients of the group's two middle samples G m + G / 2 - 1 and G m + G / 2 (the ray's last
  // sample for those beyond it) for all of them.
  const bool surfaces = mode == RenderMode::AmbientScattering && p.Surface.Active();
  auto samplePoint = [&](int s) { return InIndexUnits(o + d * (t0 + (s + 0.5) * dt), spacing); };
  auto surfaceAt = [&](int s, double sigma)
  {
    if (!surfaces)
      return SurfacePoint();
    if (!pairs)
      return classifier.SurfaceAt(samplePoint(s), sigma, p.Surface.Blending);
    const int first = s - s % group;
    return classifier.SurfaceAtMean(samplePoint(std::min(first + group / 2 - 1, n - 1)),
      samplePoint(std::min(first + group / 2, n - 1)),
      sigma,
      p.Surface.Blending);
  };
  // What a sample returns of the volumetric light (1 without surfaces).
  auto volumetricShare = [&](int s, double sigma)
  { return surfaces ? VolumetricShare(surfaceAt(s, sigma).Probability, p.Surface.Ambient) : 1.0; };
  // Ambient in-scattering from the ball around the sample s (eqs. 8.8-8.9), per unit of the
  // transmittance and of the ray's length: its sigma_t and colour, the lights at lightPoint(s).
  auto inscattered = [&](int s)
  {
    double sigma;
    Vec3 color;
    const Vec3 xs = o + d * (t0 + (s + 0.5) * dt);
    classify(xs, sigma, color);
    if (!(sigma > 0.0))
    {
      return Vec3{ 0, 0, 0 };
    }
    const Vec3 x = lightPoint(s);
    // On the light grid, read trilinearly there as the light volumes are (the GPU reads it
    // with their texture coordinate).
    const double tau = p.AmbientRadius * SampleLocalClamped(v.Averaged, x);
    const Vec3 world = geometry.LocalToWorld(x);
    Vec3 inscatter{ 0, 0, 0 };
    for (std::size_t j = 0; j < scene.Lights.size(); ++j)
    {
      const Light& light = scene.Lights[j];
      const double cosTheta = Dot(light.PropagationDirection(world), -ray.Direction);
      const double transmittance = SampleLocalClamped(v.LightVolumes[j], x);
      inscatter = inscatter +
        light.FreeIrradiance(world) * (transmittance * v.Slice.InScatteringCos(cosTheta, tau));
    }
    return Mul(color, inscatter) * (sigma * volumetricShare(s, sigma));
  };
  // The light a surface sample at x (sigma_t, colour c) reflects per unit of T (1 - e^(-sigma
  // dt)): albedo P_s sum_j E_j T_j e^(-l sigma~) (k_d c f_d + k_s f_s), each light's shadow
  // the light volume's tube transmittance times the transmittance over l = min(r, 1 / sigma~) / 2
  // (at most half a mean free path) at the averaged extinction sigma~ (SurfaceShading.h), all
  // read at lightPoint(i) as the in-scattering reads them; `surface` is surfaceAt(i, sigma).
  auto reflected = [&](int i, const Vec3& c, const SurfacePoint& surface)
  {
    Vec3 out{ 0, 0, 0 };
    if (!(surface.Probability > 0.0))
    {
      return out;
    }
    const Vec3 xl = lightPoint(i);
    const double ball =
      std::exp(-0.5 * std::min(p.AmbientRadius * SampleLocalClamped(v.Averaged, xl), 1.0));
    const Vec3 world = geometry.LocalToWorld(xl);
    for (std::size_t j = 0; j < scene.Lights.size(); ++j)
    {
      const Light& light = scene.Lights[j];
      const SurfaceReflectance r =
        Reflect(p.Surface, surface.Normal, -light.PropagationDirection(world), -ray.Direction);
      const double shadow = SampleLocalClamped(v.LightVolumes[j], xl) * ball;
      out = out +
        Mul(
          light.FreeIrradiance(world), c * r.Diffuse + Vec3{ r.Specular, r.Specular, r.Specular }) *
          shadow;
    }
    return out * (p.Albedo * surface.Probability);
  };
  Vec3 L{ 0, 0, 0 };
  if (mode == RenderMode::AmbientScattering)
  {
    // The samples 0 to lag lie within r of the ray's start, where nothing attenuates before
    // them: T r before them is 1 (eq. 8.8 with the ray starting at the camera).
    for (int i = 0; i <= lag && i < n; ++i)
    {
      L = L + inscattered(i) * dt;
    }
  }
  // The extended model's previous sample of phi along the ray (index -2: none).
  Vec3 phiBefore{ 0, 0, 0 };
  int phiBeforeIndex = -2;
  const double reducedFloor = 1.0 / std::max(1e-30, TransportLengthLimitInRadii * p.AmbientRadius);
  double T = 1.0;
  for (int i = 0; i < n && T >= p.TerminationTransmittance; ++i)
  {
    const double t = t0 + (i + 0.5) * dt;
    const Vec3 x = o + d * t;
    double sigmaT;
    Vec3 c;
    classify(x, sigmaT, c);
    const double extinction = std::exp(-sigmaT * dt);
    if (mode == RenderMode::EmissionAbsorption)
    {
      L = L + c * (T * (1.0 - extinction));
    }
    else if (mode == RenderMode::AmbientOcclusion)
    {
      double weight = p.AmbientWeight * SampleLocalClamped(v.Occlusion, x) + p.EmissionWeight;
      if (p.DirectLightWeight > 0.0 && sigmaT > 0.0)
      {
        const Vec3 world = geometry.LocalToWorld(x);
        Vec3 direct{ 0, 0, 0 };
        for (const Light& light : scene.Lights)
        {
          const double mu = Dot(light.PropagationDirection(world), -ray.Direction);
          direct =
            direct + light.FreeIrradiance(world) * (p.Albedo * HenyeyGreenstein(mu, p.Anisotropy));
        }
        L = L + Mul(c, direct) * (T * (1.0 - extinction) * p.DirectLightWeight);
      }
      L = L + c * (T * (1.0 - extinction) * weight);
    }
    else
    {
      // Emission (eq. 8.7).
      L = L + c * (T * (1.0 - p.Albedo) * sigmaT * p.EmissionWeight * dt);
      // The sample as a surface (what its diffuse field and direct light need).
      const SurfacePoint surface = surfaceAt(i, sigmaT);
      // The extended model's diffuse light: albedo c / (4 pi) per unit optical depth times
      // what the P1 field scatters towards the camera, phi + g clamp(3 J.w, -phi, phi) with
      // 3 J.w = 3 D dphi/dt along the ray (the difference from the previous sample; 0 at the
      // first), as the exact integral over the step of a source constant on it.
      // With groups, phi is read at the group's midpoint (lightPoint) and dphi/dt is the
      // difference from the group before, G steps back (0 at the ray's first group).
      if (v.Diffuse.size() == 3 && sigmaT > 0.0)
      {
        const Vec3 xl = lightPoint(i);
        auto fluence = [&](const Vec3& at)
        {
          return Vec3{ SampleLocalClamped(v.Diffuse[0], at),
            SampleLocalClamped(v.Diffuse[1], at),
            SampleLocalClamped(v.Diffuse[2], at) };
        };
        const Vec3 phi = fluence(xl);
        Vec3 slope{ 0, 0, 0 };
        if (pairs && i >= group)
        {
          slope = (phi - fluence(xl - d * (group * dt))) * (1.0 / (group * dt));
        }
        else if (!pairs && phiBeforeIndex == i - 1)
        {
          slope = (phi - phiBefore) * (1.0 / dt);
        }
        const double d3 = 1.0 /
          std::max(
            (1.0 - p.Albedo * p.Anisotropy) * SampleLocalClamped(v.Averaged, xl), reducedFloor);
        Vec3 scattered = phi;
        for (int ch = 0; ch < 3; ++ch)
        {
          // (phi itself, taken as at least 0: the relaxation may overshoot below 0 at vacuum)
          const double positive = std::max(0.0, phi[ch]);
          scattered[ch] = positive + p.Anisotropy * std::clamp(d3 * slope[ch], -positive, positive);
        }
        phiBefore = phi;
        phiBeforeIndex = i;
        Vec3 field = c;
        if (surfaces)
        {
          Vec3 facing;
          field = DiffuseFieldColor(surface.Probability,
            p.Surface,
            c,
            Facing(p.Surface, surface.Normal, -ray.Direction, facing));
        }
        L = L + Mul(field, scattered) * (T * (1.0 - extinction) * p.Albedo / (4.0 * Pi));
      }
      // Surfaces: the direct light the sample reflects.
      if (surfaces && sigmaT > 0.0)
      {
        L = L + reflected(i, c, surface) * (T * (1.0 - extinction));
      }
      // Ambient in-scattering from the ball around x' (eqs. 8.8-8.9), weighted by the
      // transmittance r before x'. x' is a sample, lag + 1 steps on, and the transmittance r
      // before it lies between this sample's T before and after its extinction: interpolated
      // linearly, T ((1 - fraction) extinction + fraction). This is the integral of
      // ALGORITHM.md section 6 on the sample grid (section "Ray casting" of ARCHITECTURE.md);
      // x' beyond the ray's end adds nothing.
      if (i + lag + 1 < n)
      {
        const double lagged = T * ((1.0 - fraction) * extinction + fraction);
        L = L + inscattered(i + lag + 1) * (lagged * dt);
      }
    }
    T *= extinction;
  }
  pixel[0] = static_cast<float>(L.x);
  pixel[1] = static_cast<float>(L.y);
  pixel[2] = static_cast<float>(L.z);
  pixel[3] = static_cast<float>(1.0 - T);
}

} // namespace

Image RenderReference(const VolumeScene& scene,
  const ScatteringParameters& p,
  const PrecomputedVolumes& volumes,
  RenderMode mode,
  const Camera& camera,
  int width,
  int height,
  const std::function<void(double)>& progress)
{
  Image image;
  image.Width = std::max(0, width);
  image.Height = std::max(0, height);
  image.Pixels.assign(4 * static_cast<std::size_t>(image.Width) * image.Height, 0.0f);
  std::atomic<int> rows{ 0 };
  Classifier classifier(scene);
  // Surfaces read the precomputed gradient, as the GPU does (SurfaceGrid.h).
  SurfaceGrid surfaces;
  if (mode == RenderMode::AmbientScattering && p.Surface.Active())
  {
    surfaces = MakeSurfaceGrid(scene);
    classifier.SetSurfaceGrid(&surfaces);
  }
  const std::thread::id caller = std::this_thread::get_id();
  ParallelFor(image.Height,
    [&](std::int64_t b, std::int64_t e)
    {
      for (std::int64_t y = b; y < e; ++y)
      {
        for (int x = 0; x < image.Width; ++x)
        {
          const Ray ray = camera.GenerateRay(x + 0.5, y + 0.5, image.Width, image.Height);
          CastRay(scene, classifier, p, volumes, mode, ray, image.At(x, static_cast<int>(y)));
        }
        const int done = ++rows;
        if (progress && std::this_thread::get_id() == caller)
        {
          progress(static_cast<double>(done) / image.Height);
        }
      }
    });
  return image;
}

} // namespace avs
