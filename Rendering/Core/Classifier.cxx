#include "Classifier.h"

#include "Extinction.h"
#include "ReferenceRenderer.h"
#include "SurfaceGrid.h"
#include "SurfaceShading.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace avs
{

namespace
{
// The nearest lattice point's value with the index clamped into the lattice.
double NearestClamped(const Grid& g, const Vec3& p)
{
  const auto& n = g.Geometry.Dimensions;
  int i[3];
  for (int a = 0; a < 3; ++a)
  {
    const double c = std::clamp(p[a], 0.0, static_cast<double>(n[a] - 1));
    i[a] = std::min(static_cast<int>(std::floor(c + 0.5)), n[a] - 1);
  }
  return g.At(i[0], i[1], i[2]);
}

// Largest sigma_t of the (linearly interpolated) opacity table over the values [lo, hi], that
// range widened by `widen` table nodes on either side.
double MaximumExtinction(const TransferFunction& tf,
  double unitDistance,
  double lo,
  double hi,
  double widen = 0.0)
{
  const std::size_t n = tf.Opacity.size();
  if (n > 1 && tf.Maximum > tf.Minimum)
  {
    const double step = (tf.Maximum - tf.Minimum) / (n - 1);
    lo -= widen * step;
    hi += widen * step;
  }
  double alpha = std::max(tf.OpacityAt(lo), tf.OpacityAt(hi));
  if (n > 1 && tf.Maximum > tf.Minimum)
  {
    const double step = (tf.Maximum - tf.Minimum) / (n - 1);
    const double a = std::clamp((lo - tf.Minimum) / step, 0.0, static_cast<double>(n - 1));
    const double b = std::clamp((hi - tf.Minimum) / step, 0.0, static_cast<double>(n - 1));
    const std::size_t first = static_cast<std::size_t>(std::ceil(a));
    const std::size_t last = static_cast<std::size_t>(b);
    for (std::size_t i = first; i <= last; ++i)
    {
      alpha = std::max(alpha, static_cast<double>(tf.Opacity[i]));
    }
  }
  return OpacityToExtinction(alpha, unitDistance);
}
} // namespace

Classifier::Classifier(const VolumeScene& scene)
  : Scene(scene)
  , Medium(scene.Medium)
{
  this->Count = std::min(4, this->Medium.NumberOfComponents());
  this->Values[0] = &scene.Scalars;
  this->Transfer[0] = &scene.Transfer;
  this->UnitDistance[0] = scene.UnitDistance;
  this->Weight[0] = this->Medium.Weight;
  this->Gradient[0] = &this->Medium.GradientOpacity;
  for (int c = 1; c < this->Count; ++c)
  {
    const MediumComponent& m = this->Medium.Components[c - 1];
    this->Values[c] = &m.Values;
    this->Transfer[c] = &m.Transfer;
    this->UnitDistance[c] = m.UnitDistance;
    this->Weight[c] = m.Weight;
    this->Gradient[c] = &m.GradientOpacity;
  }
  for (int c = 0; c < this->Count; ++c)
  {
    this->Weight[c] = std::clamp(this->Weight[c], 0.0, 1.0);
    this->AnyGradient = this->AnyGradient || !this->Gradient[c]->Opacity.empty();
  }
  const Vec3& h = scene.Scalars.Geometry.Spacing;
  const double mean = (h.x + h.y + h.z) / 3.0;
  this->GradientScale = { 0.5 * mean / h.x, 0.5 * mean / h.y, 0.5 * mean / h.z };
  this->ShadedComponent = std::min(ShadingComponent(this->Medium), this->Count - 1);
  const TransferFunction& shaded = *this->Transfer[this->ShadedComponent];
  const double range = shaded.Maximum - shaded.Minimum;
  this->InverseRange = range > 0.0 && std::isfinite(range) ? 1.0 / range : 1.0;
  for (int k = 0; k < 3; ++k)
  {
    Vec3 e{ 0, 0, 0 };
    e[k] = 1.0;
    const Vec3 local = scene.Scalars.Geometry.WorldToLocalDirection(e);
    this->ToIndex[k] = { local.x / h.x, local.y / h.y, local.z / h.z };
  }
}

bool Classifier::Sample(const Vec3& index, double s[4], double& valid) const
{
  const bool nearest = this->Medium.Sampling == Interpolation::Nearest;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int c = 0; c < this->Count; ++c)
  {
    s[c] = nearest ? this->Values[c]->NearestIndex(index, nan)
                   : this->Values[c]->SampleIndex(index, nan);
    if (!(s[c] == s[c]))
    {
      return false;
    }
  }
  valid = 1.0;
  if (!this->Medium.Validity.Values.empty())
  {
    valid = nearest ? this->Medium.Validity.NearestIndex(index, 0.0)
                    : this->Medium.Validity.SampleIndex(index, 0.0);
    for (int c = 0; c < this->Count; ++c)
    {
      s[c] = valid > 0.0 ? s[c] / valid : 0.0;
    }
  }
  return true;
}

void Classifier::SampleClamped(const Vec3& index, double s[4]) const
{
  const bool nearest = this->Medium.Sampling == Interpolation::Nearest;
  for (int c = 0; c < this->Count; ++c)
  {
    s[c] =
      nearest ? NearestClamped(*this->Values[c], index) : this->Values[c]->SampleClamped(index);
  }
  if (!this->Medium.Validity.Values.empty())
  {
    const double valid = nearest ? NearestClamped(this->Medium.Validity, index)
                                 : this->Medium.Validity.SampleClamped(index);
    for (int c = 0; c < this->Count; ++c)
    {
      s[c] = valid > 0.0 ? s[c] / valid : 0.0;
    }
  }
}

void Classifier::CentralDifferences(const Vec3& index, double d[3][4]) const
{
  for (int a = 0; a < 3; ++a)
  {
    Vec3 e{ 0, 0, 0 };
    e[a] = 1.0;
    double plus[4], minus[4];
    this->SampleClamped(index + e, plus);
    this->SampleClamped(index - e, minus);
    for (int c = 0; c < this->Count; ++c)
    {
      d[a][c] = plus[c] - minus[c];
    }
  }
}

std::array<double, 4> Classifier::GradientMagnitudes(const Vec3& index) const
{
  std::array<double, 4> squared{ 0, 0, 0, 0 };
  double d[3][4];
  this->CentralDifferences(index, d);
  for (int a = 0; a < 3; ++a)
  {
    for (int c = 0; c < this->Count; ++c)
    {
      const double g = d[a][c] * this->GradientScale[a];
      squared[c] += g * g;
    }
  }
  for (double& g : squared)
  {
    g = std::sqrt(g);
  }
  return squared;
}

Vec3 Classifier::ShadingGradient(const Vec3& index) const
{
  double d[3][4];
  this->CentralDifferences(index, d);
  const int c = this->ShadedComponent;
  return Vec3{ d[0][c], d[1][c], d[2][c] } * (0.5 * this->InverseRange);
}

double Classifier::NormalisedGradient(const Vec3& g) const
{
  // GradientScale is mean / (2 spacing): the mean spacing times d s / d x_a is 2 g_a times it.
  return 2.0 * Length(Mul(g, this->GradientScale));
}

Vec3 Classifier::SurfaceVectorAt(const Vec3& index) const
{
  if (this->Surfaces)
  {
    Vec3 v;
    double edge;
    this->Surfaces->Sample(index, this->Medium.Sampling == Interpolation::Nearest, v, edge);
    return v;
  }
  const Vec3 g = this->ShadingGradient(index);
  const Vec3& h = this->Scene.Scalars.Geometry.Spacing;
  const Vec3 local{ g.x / h.x, g.y / h.y, g.z / h.z };
  const double length = Length(local);
  return length > 0.0 ? local * (SurfaceEdge(this->NormalisedGradient(g)) / length)
                      : Vec3{ 0, 0, 0 };
}

SurfacePoint Classifier::SurfaceOf(const Vec3& v, double sigmaT, double blending) const
{
  SurfacePoint out;
  // Back to index units (times the spacing), then to world by the transpose of d index / d world.
  const Vec3 g = Mul(v, this->Scene.Scalars.Geometry.Spacing);
  const Vec3 world{ Dot(this->ToIndex[0], g), Dot(this->ToIndex[1], g), Dot(this->ToIndex[2], g) };
  const double length = Length(world);
  if (length > 0.0)
  {
    const double alpha = 1.0 - std::exp(-sigmaT * this->UnitDistance[0]);
    out.Probability = SurfaceProbabilityOfEdge(std::min(1.0, Length(v)), alpha, blending);
    out.Normal = world * (-1.0 / length);
  }
  return out;
}

SurfacePoint Classifier::SurfaceAt(const Vec3& index, double sigmaT, double blending) const
{
  return sigmaT > 0.0 ? this->SurfaceOf(this->SurfaceVectorAt(index), sigmaT, blending)
                      : SurfacePoint();
}

SurfacePoint Classifier::SurfaceAtMean(const Vec3& a,
  const Vec3& b,
  double sigmaT,
  double blending) const
{
  return sigmaT > 0.0
    ? this->SurfaceOf((this->SurfaceVectorAt(a) + this->SurfaceVectorAt(b)) * 0.5, sigmaT, blending)
    : SurfacePoint();
}

Classified Classifier::FromSamples(const Vec3& index, const double s[4], double valid) const
{
  Classified out;
  if (!(valid > 0.0))
  {
    return out;
  }
  const MediumOptions& m = this->Medium;
  double label = 0.0;
  if (m.Mask != MaskType::None && !m.MaskValues.Values.empty())
  {
    const double v = m.MaskValues.NearestIndex(index, 0.0);
    if (m.Mask == MaskType::Binary && !(v > 0.0))
    {
      return out;
    }
    label = m.Mask == MaskType::LabelMap ? std::floor(v + 0.5) : 0.0;
  }
  std::array<double, 4> gradient{ 0, 0, 0, 0 };
  if (this->AnyGradient)
  {
    gradient = this->GradientMagnitudes(index);
  }
  // sigma_t of component c from its opacity at value x, with its gradient opacity.
  auto extinction = [&](int c, double alpha)
  {
    double sigma = OpacityToExtinction(alpha, this->UnitDistance[c]);
    const TransferFunction& go = *this->Gradient[c];
    if (!go.Opacity.empty())
    {
      sigma *= std::clamp(go.OpacityAt(gradient[c]), 0.0, 1.0);
    }
    return sigma;
  };
  switch (m.Mode)
  {
    case ComponentMode::Single:
    {
      out.SigmaT = extinction(0, this->Transfer[0]->OpacityAt(s[0]));
      out.Color = this->Transfer[0]->ColorAt(s[0]);
      break;
    }
    case ComponentMode::DependentColorOpacity:
    {
      out.Color = this->Transfer[0]->ColorAt(s[0]);
      out.SigmaT = extinction(1, this->Transfer[1]->OpacityAt(s[1]));
      break;
    }
    case ComponentMode::DependentRGBA:
    {
      for (int c = 0; c < 3; ++c)
      {
        const TransferFunction& t = *this->Transfer[c];
        const double range = t.Maximum > t.Minimum ? t.Maximum - t.Minimum : 1.0;
        out.Color[c] = std::clamp((s[c] - t.Minimum) / range, 0.0, 1.0);
      }
      out.SigmaT = extinction(3, this->Transfer[3]->OpacityAt(s[3]));
      break;
    }
    case ComponentMode::Independent:
    {
      Vec3 weighted{ 0, 0, 0 };
      for (int c = 0; c < this->Count; ++c)
      {
        const double sigma = this->Weight[c] * extinction(c, this->Transfer[c]->OpacityAt(s[c]));
        out.SigmaT += sigma;
        weighted = weighted + this->Transfer[c]->ColorAt(s[c]) * sigma;
      }
      out.Color = out.SigmaT > 0.0 ? weighted * (1.0 / out.SigmaT) : Vec3{ 0, 0, 0 };
      break;
    }
  }
  const double b = std::clamp(m.MaskBlendFactor, 0.0, 1.0);
  if (label >= 1.0 && b > 0.0 && m.Mode == ComponentMode::Single)
  {
    const std::size_t l = static_cast<std::size_t>(label);
    const TransferFunction& t = l <= m.Labels.size() ? m.Labels[l - 1] : *this->Transfer[0];
    const double sigmaL = OpacityToExtinction(t.OpacityAt(s[0]), this->UnitDistance[0]);
    const double sigma = (1.0 - b) * out.SigmaT + b * sigmaL;
    out.Color = sigma > 0.0
      ? (out.Color * ((1.0 - b) * out.SigmaT) + t.ColorAt(s[0]) * (b * sigmaL)) * (1.0 / sigma)
      : Vec3{ 0, 0, 0 };
    out.SigmaT = sigma;
  }
  out.SigmaT *= valid;
  return out;
}

Classified Classifier::AtIndex(const Vec3& index) const
{
  double s[4] = { 0, 0, 0, 0 }, valid = 0.0;
  if (!this->Sample(index, s, valid))
  {
    return Classified();
  }
  return this->FromSamples(index, s, valid);
}

Classified Classifier::AtLocal(const Vec3& local) const
{
  const Vec3& h = this->Scene.Scalars.Geometry.Spacing;
  return this->AtIndex({ local.x / h.x, local.y / h.y, local.z / h.z });
}

Classified Classifier::AtWorld(const Vec3& world) const
{
  return this->AtIndex(this->Scene.Scalars.Geometry.WorldToIndex(world));
}

Classified Classifier::AtVoxel(int i, int j, int k) const
{
  double s[4] = { 0, 0, 0, 0 };
  const std::size_t id = this->Scene.Scalars.Geometry.Index(i, j, k);
  for (int c = 0; c < this->Count; ++c)
  {
    s[c] = this->Values[c]->Values[id];
  }
  double valid = 1.0;
  if (!this->Medium.Validity.Values.empty())
  {
    valid = this->Medium.Validity.Values[id];
  }
  return this->FromSamples(
    { static_cast<double>(i), static_cast<double>(j), static_cast<double>(k) }, s, valid);
}

double Classifier::Bound(const std::array<int, 3>& lo, const std::array<int, 3>& hi) const
{
  const GridGeometry& g = this->Scene.Scalars.Geometry;
  const Grid& validity = this->Medium.Validity;
  double low[4], high[4];
  std::fill(low, low + 4, std::numeric_limits<double>::infinity());
  std::fill(high, high + 4, -std::numeric_limits<double>::infinity());
  bool any = false;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i)
      {
        const std::size_t id = g.Index(i, j, k);
        if (!validity.Values.empty() && !(validity.Values[id] > 0.0f))
        {
          continue; // a NaN voxel adds no value to the samples' range
        }
        any = true;
        for (int c = 0; c < this->Count; ++c)
        {
          const double v = this->Values[c]->Values[id];
          low[c] = std::min(low[c], v);
          high[c] = std::max(high[c], v);
        }
      }
  return any ? this->BoundOfValues(low, high, false) : 0.0;
}

double Classifier::BoundOfValues(const double low[4], const double high[4], bool widen) const
{
  // Gradient opacity, validity and a binary mask only lower sigma_t; a label's medium is mixed
  // with the unlabelled one, so the larger of the two bounds both.
  const double nodes = widen ? 1.0 : 0.0;
  auto bound = [&](int c)
  { return MaximumExtinction(*this->Transfer[c], this->UnitDistance[c], low[c], high[c], nodes); };
  const MediumOptions& m = this->Medium;
  double result = 0.0;
  switch (m.Mode)
  {
    case ComponentMode::Single:
      result = bound(0);
      if (m.Mask == MaskType::LabelMap)
      {
        for (const TransferFunction& t : m.Labels)
        {
          result =
            std::max(result, MaximumExtinction(t, this->UnitDistance[0], low[0], high[0], nodes));
        }
      }
      break;
    case ComponentMode::DependentColorOpacity:
      result = bound(1);
      break;
    case ComponentMode::DependentRGBA:
      result = bound(3);
      break;
    case ComponentMode::Independent:
      for (int c = 0; c < this->Count; ++c)
      {
        result += this->Weight[c] * bound(c);
      }
      break;
  }
  return result;
}

std::vector<double> ExtinctionKey(const VolumeScene& scene)
{
  std::vector<double> key;
  auto add = [&key](const TransferFunction& t)
  {
    key.push_back(static_cast<double>(t.Opacity.size()));
    key.push_back(t.Minimum);
    key.push_back(t.Maximum);
    key.insert(key.end(), t.Opacity.begin(), t.Opacity.end());
  };
  const MediumOptions& m = scene.Medium;
  key.push_back(static_cast<double>(m.Mode));
  key.push_back(static_cast<double>(m.Sampling));
  key.push_back(static_cast<double>(m.Mask));
  key.push_back(m.MaskBlendFactor);
  key.push_back(scene.UnitDistance);
  key.push_back(m.Weight);
  add(scene.Transfer);
  add(m.GradientOpacity);
  for (const MediumComponent& c : m.Components)
  {
    key.push_back(c.UnitDistance);
    key.push_back(c.Weight);
    add(c.Transfer);
    add(c.GradientOpacity);
  }
  for (const TransferFunction& t : m.Labels)
  {
    add(t);
  }
  return key;
}

namespace
{
void AddColors(std::vector<double>& key, const TransferFunction& t)
{
  key.push_back(static_cast<double>(t.Color.size()));
  for (const std::array<float, 3>& c : t.Color)
  {
    key.insert(key.end(), c.begin(), c.end());
  }
}
} // namespace

std::vector<double> AppearanceKey(const VolumeScene& scene)
{
  std::vector<double> key = ExtinctionKey(scene);
  const MediumOptions& m = scene.Medium;
  AddColors(key, scene.Transfer);
  for (const MediumComponent& c : m.Components)
  {
    AddColors(key, c.Transfer);
  }
  for (const TransferFunction& t : m.Labels)
  {
    AddColors(key, t);
  }
  return key;
}

} // namespace avs
