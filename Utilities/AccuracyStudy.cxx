#include "AccuracyStudy.h"

#include "PathTracer.h"
#include "ProceduralVolume.h"

#include "vtkAVSDataTranslator.h"
#include "vtkAVSPropertyTranslator.h"
#include "vtkAVSSceneTranslator.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace
{
struct StudyScene
{
  std::string Name;
  avs::Grid Density;
  vtkSmartPointer<vtkVolumeProperty> Property;
  double Albedo = 0.9;
  double Anisotropy = 0.0;
  std::vector<vtkSmartPointer<vtkLight>> Lights;
};

vtkSmartPointer<vtkLight> Directional(const avs::Vec3& from,
  double intensity,
  const avs::Vec3& color)
{
  auto l = vtkSmartPointer<vtkLight>::New();
  l->SetLightTypeToSceneLight();
  l->SetPositional(false);
  l->SetPosition(from.x, from.y, from.z);
  l->SetFocalPoint(0, 0, 0);
  l->SetDiffuseColor(color.x, color.y, color.z);
  l->SetIntensity(intensity / (4.0 * avs::Pi)); // `intensity` is the irradiance
  return l;
}

vtkSmartPointer<vtkVolumeProperty> Property(double opacity,
  double unitDistance,
  const std::vector<std::pair<double, avs::Vec3>>& colors,
  double threshold)
{
  auto p = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> c;
  for (const auto& [s, rgb] : colors)
  {
    c->AddRGBPoint(s, rgb.x, rgb.y, rgb.z);
  }
  vtkNew<vtkPiecewiseFunction> o;
  o->AddPoint(0.0, 0.0);
  o->AddPoint(threshold, 0.0);
  o->AddPoint(1.0, opacity);
  p->SetColor(c);
  p->SetScalarOpacity(o);
  p->SetScalarOpacityUnitDistance(unitDistance);
  p->SetInterpolationTypeToLinear();
  return p;
}

// A dense, medical-like volume: a thick ellipsoidal shell (bone-like) around a lumpy interior.
avs::Grid MakeDense(int n)
{
  avs::Grid g = avs::MakeCloud(n, 3);
  const auto& geo = g.Geometry;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const avs::Vec3 p = geo.IndexToWorld({ double(i), double(j), double(k) });
        const double r = avs::Length(avs::Vec3{ p.x / 0.85, p.y / 0.7, p.z / 0.8 });
        const double shell = std::abs(r - 0.85) < 0.06 ? 1.0 : 0.0;
        const double inside = r < 0.8 ? 0.35 + 0.4 * avs::FractalNoise(p * 4.0, 3, 21) : 0.0;
        g.At(i, j, k) = static_cast<float>(std::max(shell, inside));
      }
  return g;
}

StudyScene MakeScene(const std::string& name, int voxels, double cloudOpacity)
{
  StudyScene s;
  s.Name = name;
  const avs::Vec3 white{ 1, 1, 1 };
  if (name == "cloud_back" || name == "cloud_side")
  {
    s.Density = avs::MakeCloud(voxels);
    s.Property = Property(cloudOpacity, 2.0 / 40.0, { { 0.0, white }, { 1.0, white } }, 0.05);
    s.Albedo = 0.95;
    s.Anisotropy = 0.6;
    s.Lights.push_back(name == "cloud_back" ? Directional({ -0.3, 0.6, -1.0 }, 9.0, white)
                                            : Directional({ -1.0, 0.25, 0.1 }, 9.0, white));
  }
  else if (name == "nebula_point")
  {
    s.Density = avs::MakeNebula(voxels);
    s.Property = Property(0.45,
      2.0 / 40.0,
      { { 0.0, { 0.3, 0.4, 0.9 } }, { 0.5, { 0.8, 0.6, 0.9 } }, { 1.0, { 1.0, 0.85, 0.6 } } },
      0.05);
    s.Albedo = 0.9;
    s.Anisotropy = 0.2;
    auto lamp = vtkSmartPointer<vtkLight>::New();
    lamp->SetLightTypeToSceneLight();
    lamp->SetPositional(true);
    lamp->SetConeAngle(180);
    lamp->SetPosition(0, 0, 0);
    lamp->SetFocalPoint(0, 0, -1);
    lamp->SetDiffuseColor(1.0, 0.85, 0.6);
    lamp->SetIntensity(3.0 / (4.0 * avs::Pi)); // irradiance 3
    lamp->SetAttenuationValues(0.2, 0.0, 4.0);
    s.Lights.push_back(lamp);
  }
  else if (name == "plume_point")
  {
    // A point light inside a dense plume (the study's cloud at the given opacity), with VTK's
    // default attenuation (1, 0, 0): no falloff with distance.
    s.Density = avs::MakeCloud(voxels);
    s.Property = Property(cloudOpacity, 2.0 / 40.0, { { 0.0, white }, { 1.0, white } }, 0.05);
    s.Albedo = 0.95;
    s.Anisotropy = 0.6;
    auto lamp = vtkSmartPointer<vtkLight>::New();
    lamp->SetLightTypeToSceneLight();
    lamp->SetPositional(true);
    lamp->SetConeAngle(180);
    lamp->SetPosition(0, 0, 0);
    lamp->SetFocalPoint(0, 0, -1);
    lamp->SetIntensity(1.5 / (4.0 * avs::Pi)); // irradiance 1.5
    lamp->SetAttenuationValues(1.0, 0.0, 0.0);
    s.Lights.push_back(lamp);
  }
  else // dense_medical
  {
    s.Density = MakeDense(voxels);
    s.Property = Property(0.8,
      2.0 / 60.0,
      { { 0.0, { 0.9, 0.6, 0.5 } }, { 0.6, { 0.95, 0.75, 0.65 } }, { 1.0, white } },
      0.2);
    s.Albedo = 0.5;
    s.Anisotropy = 0.0;
    s.Lights.push_back(Directional({ -0.6, 0.8, 0.6 }, 10.0, white));
    s.Lights.push_back(Directional({ 0.4, -0.2, 1.0 }, 5.0, white));
  }
  return s;
}

vtkSmartPointer<vtkImageData> ToImageData(const avs::Grid& g)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(
    g.Geometry.Dimensions[0], g.Geometry.Dimensions[1], g.Geometry.Dimensions[2]);
  image->SetSpacing(g.Geometry.Spacing.x, g.Geometry.Spacing.y, g.Geometry.Spacing.z);
  image->SetOrigin(g.Geometry.Origin.x, g.Geometry.Origin.y, g.Geometry.Origin.z);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(static_cast<vtkIdType>(g.Values.size()));
  std::copy(g.Values.begin(), g.Values.end(), a->GetPointer(0));
  image->GetPointData()->SetScalars(a);
  return image;
}

void PlaceCamera(vtkCamera* camera)
{
  camera->SetPosition(0.35, 0.45, 4.3);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  camera->SetClippingRange(1.0, 10.0);
}

double Sum(const std::vector<double>& values)
{
  double sum = 0.0;
  for (double v : values)
  {
    sum += v;
  }
  return sum;
}

// `picture` scaled by the factor that minimises its RMSE against `reference` (VTK's shaded
// mapper at its best exposure), clamped to [0, 1] as the pictures are.
std::vector<double> AtBestExposure(std::vector<double> picture,
  const std::vector<double>& reference)
{
  double pr = 0.0, pp = 0.0;
  for (std::size_t i = 0; i < picture.size(); ++i)
  {
    pr += picture[i] * reference[i];
    pp += picture[i] * picture[i];
  }
  const double scale = pp > 0.0 ? pr / pp : 1.0;
  for (double& v : picture)
  {
    v = std::clamp(v * scale, 0.0, 1.0);
  }
  return picture;
}

AccuracyResult Measured(const std::string& scene,
  const std::string& model,
  const std::vector<double>& picture,
  const std::vector<double>& reference,
  double noise)
{
  double l1 = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i)
  {
    l1 += std::abs(picture[i] - reference[i]);
    norm += std::abs(reference[i]);
  }
  AccuracyResult r;
  r.Scene = scene;
  r.Model = model;
  r.Rmse = AccuracyRmse(picture, reference);
  r.RelativeL1 = norm > 0 ? l1 / norm : 0.0;
  r.TruthNoise = noise;
  return r;
}

// A path-traced picture, from the settings' cache folder when it holds it (same scene, sizes,
// paths, cloud opacity and radius), rendered and kept there otherwise.
template<typename Render>
std::vector<double> TruthPicture(const AccuracySettings& s,
  const std::string& scene,
  int run,
  Render&& render)
{
  std::string file;
  if (!s.TruthCache.empty())
  {
    char key[256];
    std::snprintf(key,
      sizeof(key),
      "/%s-%d-%d-%d-%.4f-%.4f-%d.truth",
      scene.c_str(),
      s.ImageSize,
      s.Voxels,
      s.SamplesPerPixel,
      s.CloudOpacity,
      s.AmbientRadius,
      run);
    file = s.TruthCache + key;
    std::ifstream in(file, std::ios::binary);
    std::vector<double> cached(3 * static_cast<std::size_t>(s.ImageSize) * s.ImageSize);
    if (in.read(reinterpret_cast<char*>(cached.data()),
          static_cast<std::streamsize>(cached.size() * sizeof(double))))
    {
      return cached;
    }
  }
  std::vector<double> picture = ClampedRgb(render());
  if (!file.empty())
  {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(picture.data()),
      static_cast<std::streamsize>(picture.size() * sizeof(double)));
  }
  return picture;
}

// The path tracer's settings of the study's truth for `seed`.
avs::PathTracerSettings TruthSettings(const AccuracySettings& settings, std::uint64_t seed)
{
  avs::PathTracerSettings pts;
  pts.SamplesPerPixel = settings.SamplesPerPixel;
  pts.Seed = seed;
  return pts;
}
} // namespace

bool CheckAccuracySettings(const AccuracySettings& settings, const char* program)
{
  std::vector<std::string> known = AccuracySettings().Scenes;
  known.push_back("plume_point"); // not in the default list
  if (settings.Scenes.empty())
  {
    std::fprintf(stderr, "%s: no scenes to render\n", program);
    return false;
  }
  for (const std::string& name : settings.Scenes)
  {
    if (std::find(known.begin(), known.end(), name) == known.end())
    {
      std::fprintf(stderr, "%s: unknown scene '%s'\n", program, name.c_str());
      return false;
    }
  }
  if (!(settings.CloudOpacity > 0.0 && settings.CloudOpacity <= 1.0))
  {
    std::fprintf(stderr, "%s: the cloud opacity must be in (0, 1]\n", program);
    return false;
  }
  if (!(settings.AmbientRadius >= 0.0 && std::isfinite(settings.AmbientRadius)))
  {
    std::fprintf(stderr, "%s: the ambient radius must be finite and >= 0\n", program);
    return false;
  }
  return true;
}

AccuracyScene SetUpAccuracyScene(const AccuracySettings& settings,
  const std::string& name,
  vtkRenderer* renderer)
{
  StudyScene scene = MakeScene(name, settings.Voxels, settings.CloudOpacity);
  AccuracyScene out;
  out.Name = settings.Shade ? name + "_shaded" : name;
  if (settings.Shade)
  {
    scene.Property->ShadeOn();
  }
  out.Data = ToImageData(scene.Density);
  out.Property = scene.Property;
  out.Albedo = scene.Albedo;
  out.Anisotropy = scene.Anisotropy;
  for (const auto& l : scene.Lights)
  {
    renderer->AddLight(l);
  }
  PlaceCamera(renderer->GetActiveCamera());

  // The path tracer's scene.
  std::string error, warning;
  vtkAVSDataTranslator::Volume volume;
  vtkAVSDataTranslator::ToVolume(out.Data, {}, volume, error, warning);
  out.Core.Scalars = std::move(volume.Components.at(0));
  vtkAVSPropertyTranslator::ToMedium(
    scene.Property, { { 0.0, 1.0 } }, VTK_FLOAT, false, out.Core, error, warning);
  out.Core.Lights = vtkAVSSceneTranslator::ToLights(renderer, renderer->GetActiveCamera());
  avs::ScatteringParameters p;
  p.AmbientRadius = settings.AmbientRadius;
  p.Albedo = scene.Albedo;
  p.Anisotropy = scene.Anisotropy;
  p.Surface = vtkAVSPropertyTranslator::ToSurface(scene.Property, settings.Blending, renderer);
  out.Parameters = p.Resolve(out.Core.Scalars.Geometry);
  out.Camera = vtkAVSSceneTranslator::ToCamera(renderer->GetActiveCamera());
  return out;
}

void ConfigureAccuracyMapper(vtkAmbientScatteringVolumeMapper* mapper,
  const AccuracyScene& scene,
  const AccuracySettings& settings)
{
  mapper->SetAmbientRadius(settings.AmbientRadius);
  mapper->SetAlbedo(scene.Albedo);
  mapper->SetAnisotropy(scene.Anisotropy);
  mapper->SetVolumetricScatteringBlending(static_cast<float>(settings.Blending));
  mapper->UseJitteringOff();
  // The truth is linear: the lit mappers are measured on their radiance (exposure 1, no tone
  // curve), as EA and AO are.
  mapper->SetExposure(1.0);
  mapper->SetToneMappingToClamp();
}

std::vector<double> AccuracyTruth(const AccuracySettings& settings,
  const AccuracyScene& scene,
  double* noise)
{
  // The path tracer, twice with different seeds to measure its own noise.
  const int size = settings.ImageSize;
  std::vector<double> truth[2];
  for (int run = 0; run < 2; ++run)
  {
    const avs::PathTracerSettings pts = TruthSettings(settings, 17 + run);
    const auto render = [&]
    { return avs::RenderPathTraced(scene.Core, scene.Parameters, pts, scene.Camera, size, size); };
    truth[run] = TruthPicture(settings, scene.Name, run, render);
  }
  // Noise of the mean of both runs: the RMSE between them / 2.
  double se = 0.0;
  std::vector<double> reference(truth[0].size());
  for (std::size_t i = 0; i < reference.size(); ++i)
  {
    reference[i] = 0.5 * (truth[0][i] + truth[1][i]);
    se += (truth[0][i] - truth[1][i]) * (truth[0][i] - truth[1][i]);
  }
  if (noise)
  {
    *noise = std::sqrt(se / reference.size()) / 2.0;
  }
  return reference;
}

std::vector<double> AccuracyGrab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  vtkDataArray* s = grab->GetOutput()->GetPointData()->GetScalars();
  std::vector<double> out(3 * s->GetNumberOfTuples());
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
    for (int c = 0; c < 3; ++c)
      out[3 * i + c] = s->GetComponent(i, c) / 255.0;
  return out;
}

std::vector<double> ClampedRgb(const avs::Image& image)
{
  std::vector<double> out(3 * static_cast<std::size_t>(image.Width) * image.Height);
  for (int y = 0; y < image.Height; ++y)
    for (int x = 0; x < image.Width; ++x)
      for (int c = 0; c < 3; ++c)
        out[3 * (static_cast<std::size_t>(y) * image.Width + x) + c] =
          std::clamp(static_cast<double>(image.At(x, y)[c]), 0.0, 1.0);
  return out;
}

double AccuracyRmse(const std::vector<double>& picture, const std::vector<double>& reference)
{
  double se = 0.0;
  for (std::size_t i = 0; i < reference.size(); ++i)
  {
    const double d = picture[i] - reference[i];
    se += d * d;
  }
  return std::sqrt(se / reference.size());
}

vtkSmartPointer<vtkImageData> AccuracyPicture(const std::vector<double>& rgb,
  int size,
  double scale)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(size, size, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (std::size_t i = 0; i < rgb.size(); ++i)
  {
    p[i] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(rgb[i] * scale, 0.0, 1.0)));
  }
  return image;
}

bool RunAccuracyStudy(const AccuracySettings& settings,
  std::vector<AccuracyResult>& results,
  double* pathTracerNoise)
{
  if (!CheckAccuracySettings(settings, "avs-accuracy"))
  {
    return false;
  }
  const int size = settings.ImageSize;
  vtkNew<vtkImageAppend> rows;
  rows->SetAppendAxis(1);
  double worstNoise = 0.0;
  for (const std::string& name : settings.Scenes)
  {
    vtkNew<vtkRenderWindow> window;
    window->SetSize(size, size);
    window->SetMultiSamples(0);
    window->OffScreenRenderingOn();
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0, 0, 0);
    window->AddRenderer(renderer);
    const AccuracyScene scene = SetUpAccuracyScene(settings, name, renderer);
    const auto& data = scene.Data;

    // The path tracer (truth).
    double noise = 0.0;
    const std::vector<double> reference = AccuracyTruth(settings, scene, &noise);
    worstNoise = std::max(worstNoise, noise);

    // The mappers; EA and AO get k = albedo * sum of irradiances at the centre / 4 pi.
    double k = 0.0;
    for (const avs::Light& l : scene.Core.Lights)
    {
      const avs::Vec3 e = l.FreeIrradiance({ 0, 0, 0 });
      k += scene.Albedo * (e.x + e.y + e.z) / 3.0 / (4.0 * avs::Pi);
    }
    vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
    vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
    vtkNew<vtkAmbientScatteringVolumeMapper> as; // the paper's model
    as->SetScatteringModelToPaper();
    ao->SetAmbientWeight(k);
    ao->SetOcclusionRadius(settings.AmbientRadius);
    ConfigureAccuracyMapper(as, scene, settings);
    vtkNew<vtkAmbientScatteringVolumeMapper> asx; // the extended model
    ConfigureAccuracyMapper(asx, scene, settings);
    asx->SetScatteringModelToExtended();

    // EA's colours scaled by k (clamped at 1 by the transfer function). EA, AO and the unshaded
    // extended model get the property with ShadeOff.
    vtkNew<vtkVolumeProperty> unshaded;
    unshaded->DeepCopy(scene.Property);
    unshaded->ShadeOff();
    vtkNew<vtkAmbientScatteringVolumeMapper> asxOff; // the extended model with ShadeOff
    ConfigureAccuracyMapper(asxOff, scene, settings);
    vtkNew<vtkGPUVolumeRayCastMapper> vtkShaded; // VTK's, ShadeOn, at its best exposure
    vtkShaded->SetSampleDistance(0.5 * 2.0 / (settings.Voxels - 1));
    vtkShaded->AutoAdjustSampleDistancesOff();
    vtkNew<vtkVolumeProperty> eaProperty;
    eaProperty->DeepCopy(unshaded);
    vtkNew<vtkColorTransferFunction> scaled;
    scaled->DeepCopy(scene.Property->GetRGBTransferFunction(0));
    for (int i = 0; i < scaled->GetSize(); ++i)
    {
      double node[6];
      scaled->GetNodeValue(i, node);
      for (int c = 1; c <= 3; ++c)
      {
        node[c] = std::min(1.0, node[c] * k);
      }
      scaled->SetNodeValue(i, node);
    }
    eaProperty->SetColor(scaled);
    std::vector<std::string> models{ "ea", "ao", "as", "asx" };
    std::vector<vtkAVSVolumeMapper*> mappers{ ea, ao, as, asx };
    std::vector<vtkVolumeProperty*> properties{
      eaProperty, unshaded, scene.Property, scene.Property
    };
    if (settings.Shade)
    {
      models.insert(models.end(), { "asx_off", "vtk" });
      mappers.insert(mappers.end(), { asxOff, nullptr });
      properties.insert(properties.end(), { unshaded, scene.Property });
    }
    const int count = static_cast<int>(models.size());
    std::vector<std::vector<double>> pictures(models.size());
    for (int m = 0; m < count; ++m)
    {
      vtkVolumeMapper* mapper = mappers[m] ? static_cast<vtkVolumeMapper*>(mappers[m])
                                           : static_cast<vtkVolumeMapper*>(vtkShaded);
      mapper->SetInputData(data);
      if (mappers[m])
      {
        mappers[m]->UseJitteringOff();
      }
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(properties[m]);
      renderer->AddVolume(volume);
      window->Render();
      pictures[m] = AccuracyGrab(window);
      renderer->RemoveVolume(volume);
      if (mappers[m] && mappers[m]->GetNumberOfRenderedFrames() != 1)
      {
        std::fprintf(stderr,
          "avs-accuracy: the %s mapper did not render %s\n",
          models[m].c_str(),
          name.c_str());
        return false;
      }
      if (!mappers[m])
      {
        pictures[m] = AtBestExposure(pictures[m], reference);
      }
      results.push_back(Measured(scene.Name, models[m], pictures[m], reference, noise));
    }
    for (int m = 0; m < count; ++m)
    {
      results[results.size() - count + m].MeanRatio =
        Sum(reference) > 0 ? Sum(pictures[m]) / Sum(reference) : 0.0;
    }
    if (settings.Verbose)
    {
      // Where the light comes from: the truth's single-scattered share (one bounce, same seed),
      // and each model's mean radiance against the truth's (below 1: too dark on average).
      avs::PathTracerSettings single = TruthSettings(settings, 17);
      single.MaximumBounces = 1;
      const auto& camera = scene.Camera;
      const auto render = [&]
      { return avs::RenderPathTraced(scene.Core, scene.Parameters, single, camera, size, size); };
      const std::vector<double> once = TruthPicture(settings, name, 2, render);
      const double truthSum = Sum(reference);
      std::fprintf(stderr,
        "[avs-accuracy] %s: k = %.3f, path-tracer noise (RMSE) %.4f, single scattering %.0f %% "
        "of the truth, mean radiance / truth: ea %.2f ao %.2f as %.2f asx %.2f\n",
        name.c_str(),
        k,
        noise,
        truthSum > 0 ? 100.0 * Sum(once) / truthSum : 0.0,
        results[results.size() - count].MeanRatio,
        results[results.size() - count + 1].MeanRatio,
        results[results.size() - count + 2].MeanRatio,
        results[results.size() - count + 3].MeanRatio);
    }
    if (!settings.OutputPicture.empty())
    {
      vtkNew<vtkImageAppend> row;
      row->SetAppendAxis(0);
      row->AddInputData(AccuracyPicture(reference, size));
      for (int m = 0; m < count; ++m)
      {
        row->AddInputData(AccuracyPicture(pictures[m], size));
      }
      for (int m = 0; m < count; ++m)
      {
        std::vector<double> diff(reference.size());
        for (std::size_t i = 0; i < diff.size(); ++i)
        {
          diff[i] = std::abs(pictures[m][i] - reference[i]);
        }
        row->AddInputData(AccuracyPicture(diff, size, 4.0));
      }
      row->Update();
      vtkNew<vtkImageData> copy;
      copy->DeepCopy(row->GetOutput());
      rows->AddInputData(copy);
    }
  }
  if (!settings.OutputPicture.empty())
  {
    rows->Update();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(rows->GetOutputPort());
    writer->SetFileName(settings.OutputPicture.c_str());
    writer->Write();
  }
  if (pathTracerNoise)
  {
    *pathTracerNoise = worstNoise;
  }
  return true;
}
