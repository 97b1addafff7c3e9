#include "vtkAVSPropertyTranslator.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace
{
using Table = avs::TransferFunction;

// Colour and opacity functions sampled over [lo, hi] into `tf`.
void Sample(vtkColorTransferFunction* rgb,
  vtkPiecewiseFunction* gray,
  vtkPiecewiseFunction* opacityFunction,
  double lo,
  double hi,
  Table& tf)
{
  const int n = vtkAVSPropertyTranslator::TableSize;
  tf = Table();
  tf.Minimum = lo;
  tf.Maximum = hi;
  std::vector<float> color(3 * n, 0.0f), opacity(n, 0.0f);
  if (gray)
  {
    gray->GetTable(lo, hi, n, opacity.data());
    for (int i = 0; i < n; ++i)
    {
      color[3 * i] = color[3 * i + 1] = color[3 * i + 2] = opacity[i];
    }
  }
  else if (rgb)
  {
    rgb->GetTable(lo, hi, n, color.data());
  }
  std::fill(opacity.begin(), opacity.end(), 0.0f);
  if (opacityFunction)
  {
    opacityFunction->GetTable(lo, hi, n, opacity.data());
  }
  for (int i = 0; i < n; ++i)
  {
    tf.Color.push_back({ std::clamp(color[3 * i], 0.0f, 1.0f),
      std::clamp(color[3 * i + 1], 0.0f, 1.0f),
      std::clamp(color[3 * i + 2], 0.0f, 1.0f) });
    tf.Opacity.push_back(std::clamp(opacity[i], 0.0f, 1.0f));
  }
}

// The range [lo, hi] of a component, widened when empty.
std::array<double, 2> Widened(const std::array<double, 2>& r)
{
  return { r[0], r[1] > r[0] ? r[1] : r[0] + 1.0 };
}

// The gradient-opacity table of property function `index` for a component of range `r`: VTK's
// table over gradient magnitudes [0, a quarter of the range]. Empty when the property has none
// or it is disabled.
Table GradientTable(vtkVolumeProperty* property, int index, const std::array<double, 2>& r)
{
  Table go;
  if (!property->HasGradientOpacity(index) || property->GetDisableGradientOpacity(index))
  {
    return go;
  }
  vtkPiecewiseFunction* f = property->GetStoredGradientOpacity(index);
  if (!f)
  {
    return go;
  }
  const int n = vtkAVSPropertyTranslator::TableSize;
  go.Minimum = 0.0;
  go.Maximum = 0.25 * (r[1] > r[0] ? r[1] - r[0] : 1.0);
  go.Opacity.assign(n, 0.0f);
  f->GetTable(go.Minimum, go.Maximum, n, go.Opacity.data());
  for (float& v : go.Opacity)
  {
    v = std::clamp(v, 0.0f, 1.0f);
  }
  // A function of 1 everywhere multiplies by 1: no gradient opacity, and no gradients to compute
  // (six more fetches per sample). VTK creates one wherever its gradient-opacity getter finds
  // none (GetStoredGradientOpacity, vtkVolumeProperty::DeepCopy), so a property that was only
  // read or copied has one.
  if (std::all_of(go.Opacity.begin(), go.Opacity.end(), [](float v) { return v == 1.0f; }))
  {
    return Table();
  }
  return go;
}

// The values that VTK's volume texture maps to [0, 1] for a scalar type (normalised integer
// textures; floats as they are; wider types are scaled over their range before the upload).
std::array<double, 2> DirectColorRange(int scalarType, const std::array<double, 2>& range)
{
  switch (scalarType)
  {
    case VTK_UNSIGNED_CHAR:
      return { 0.0, 255.0 };
    case VTK_SIGNED_CHAR:
      return { 0.0, 127.0 };
    case VTK_UNSIGNED_SHORT:
      return { 0.0, 65535.0 };
    case VTK_SHORT:
      return { 0.0, 32767.0 };
    case VTK_FLOAT:
      return { 0.0, 1.0 };
    default:
      return Widened(range);
  }
}

bool UnitDistance(vtkVolumeProperty* property, int index, double& u, std::string& error)
{
  u = property->GetScalarOpacityUnitDistance(index);
  if (!std::isfinite(u) || !(u > 0.0))
  {
    error = "the scalar opacity unit distance must be finite and positive";
    return false;
  }
  return true;
}
} // namespace

bool vtkAVSPropertyTranslator::ToTransferFunction(vtkVolumeProperty* property,
  int index,
  double lo,
  double hi,
  avs::TransferFunction& tf,
  std::string& error)
{
  if (!property)
  {
    error = "no volume property";
    return false;
  }
  if (!std::isfinite(lo) || !std::isfinite(hi))
  {
    error = "the scalar range is not finite";
    return false;
  }
  const auto r = Widened({ lo, hi });
  const bool gray = property->GetColorChannels(index) == 1;
  Sample(gray ? nullptr : property->GetRGBTransferFunction(index),
    gray ? property->GetGrayTransferFunction(index) : nullptr,
    property->GetScalarOpacity(index),
    r[0],
    r[1],
    tf);
  return true;
}

bool vtkAVSPropertyTranslator::ToMedium(vtkVolumeProperty* property,
  const std::vector<std::array<double, 2>>& ranges,
  int scalarType,
  bool labelMap,
  avs::VolumeScene& scene,
  std::string& error,
  std::string& warning)
{
  warning.clear();
  if (!property)
  {
    error = "no volume property";
    return false;
  }
  if (property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D)
  {
    error = "2D transfer functions (TransferFunctionMode TF_2D) are not supported";
    return false;
  }
  const int count = static_cast<int>(ranges.size());
  if (count < 1 || count > 4)
  {
    error = "unsupported number of scalar components: " + std::to_string(count);
    return false;
  }
  for (const auto& r : ranges)
  {
    if (!std::isfinite(r[0]) || !std::isfinite(r[1]))
    {
      error = "the scalar range is not finite";
      return false;
    }
  }
  avs::MediumOptions& m = scene.Medium;
  m.Components.resize(static_cast<std::size_t>(count - 1));
  m.Sampling = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
    ? avs::Interpolation::Nearest
    : avs::Interpolation::Linear;
  m.Weight = 1.0;
  m.GradientOpacity = Table();
  m.Labels.clear();
  const bool independent = count == 1 || property->GetIndependentComponents();
  if (!independent && count != 2 && count != 4)
  {
    std::ostringstream os;
    os << "dependent components (IndependentComponentsOff) need 2 components (colour and "
          "opacity) or 4 (RGB and opacity), not "
       << count << "; for " << count << " channels use IndependentComponentsOn";
    error = os.str();
    return false;
  }
  m.Mode = count == 1 ? avs::ComponentMode::Single
                      : (independent ? avs::ComponentMode::Independent
                                     : (count == 2 ? avs::ComponentMode::DependentColorOpacity
                                                   : avs::ComponentMode::DependentRGBA));
  // The functions of component c (1..count-1) go into m.Components[c - 1].
  auto transferOf = [&](int c) -> Table&
  { return c == 0 ? scene.Transfer : m.Components[c - 1].Transfer; };
  auto unitOf = [&](int c) -> double&
  { return c == 0 ? scene.UnitDistance : m.Components[c - 1].UnitDistance; };
  auto gradientOf = [&](int c) -> Table&
  { return c == 0 ? m.GradientOpacity : m.Components[c - 1].GradientOpacity; };
  for (int c = 0; c < count; ++c)
  {
    gradientOf(c) = Table();
    if (c > 0)
    {
      m.Components[c - 1].Weight = 1.0;
    }
  }
  if (independent)
  {
    for (int c = 0; c < count; ++c)
    {
      if (!ToTransferFunction(property, c, ranges[c][0], ranges[c][1], transferOf(c), error) ||
        !UnitDistance(property, c, unitOf(c), error))
      {
        return false;
      }
      gradientOf(c) = GradientTable(property, c, ranges[c]);
      const double w = count > 1 ? std::clamp(property->GetComponentWeight(c), 0.0, 1.0) : 1.0;
      if (c == 0)
      {
        m.Weight = w;
      }
      else
      {
        m.Components[c - 1].Weight = w;
      }
    }
  }
  else
  {
    // VTK's dependent components: colour function 0 over component 0 (2 components) or RGB
    // straight from components 0-2 (4), opacity function 0 over the last component with the
    // unit distance of that component's index, gradient opacity 0 on it.
    const int last = count - 1;
    for (int c = 0; c < last; ++c)
    {
      // RGBA: the colour is the component as VTK's texture holds it, [0, 1] over r.
      const auto r = count == 4 ? DirectColorRange(scalarType, ranges[c]) : Widened(ranges[c]);
      if (!ToTransferFunction(property, 0, r[0], r[1], transferOf(c), error))
      {
        return false;
      }
      unitOf(c) = 1.0;
    }
    if (!ToTransferFunction(
          property, 0, ranges[last][0], ranges[last][1], transferOf(last), error) ||
      !UnitDistance(property, last, unitOf(last), error))
    {
      return false;
    }
    gradientOf(last) = GradientTable(property, 0, ranges[last]);
  }
  if (labelMap)
  {
    if (count != 1)
    {
      error = "label-map masks need single-component scalars";
      return false;
    }
    const std::set<int> labels = property->GetLabelMapLabels();
    const int largest = labels.empty() ? 0 : *labels.rbegin();
    for (int label = 1; label <= largest; ++label)
    {
      vtkColorTransferFunction* color = property->GetLabelColor(label);
      vtkPiecewiseFunction* opacity = property->GetLabelScalarOpacity(label);
      Table t;
      const auto r = Widened(ranges[0]);
      const bool gray = property->GetColorChannels(0) == 1;
      Sample(color ? color : (gray ? nullptr : property->GetRGBTransferFunction(0)),
        color || !gray ? nullptr : property->GetGrayTransferFunction(0),
        opacity ? opacity : property->GetScalarOpacity(0),
        r[0],
        r[1],
        t);
      m.Labels.push_back(std::move(t));
    }
    if (property->HasLabelGradientOpacity())
    {
      warning = "label gradient opacity (SetLabelGradientOpacity) is not supported: labelled "
                "voxels take no gradient opacity";
    }
  }
  return true;
}

avs::SurfaceShading vtkAVSPropertyTranslator::ToSurface(vtkVolumeProperty* property,
  double blending,
  vtkRenderer* renderer)
{
  avs::SurfaceShading s;
  s.Blending = blending;
  s.TwoSided = !renderer || renderer->GetTwoSidedLighting() != 0;
  if (property)
  {
    s.Shade = property->GetShade(0) != 0;
    s.Ambient = property->GetAmbient(0);
    s.Diffuse = property->GetDiffuse(0);
    s.Specular = property->GetSpecular(0);
    s.SpecularPower = property->GetSpecularPower(0);
  }
  return s;
}
