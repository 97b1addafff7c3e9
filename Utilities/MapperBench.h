// The harness of avs-bench-mappers: a window, a renderer, the scene's property, volume and
// lights, and the timing of frames of several mappers in alternation (MeasureEach, RatioOf) and
// of interaction as vtkRenderWindowInteractor drives it (Interact).
#ifndef avs_MapperBench_h
#define avs_MapperBench_h

#include "vtkAVSVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

inline double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

inline double Seconds(const std::chrono::steady_clock::time_point& start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A value vtkObject::Print writes after `label` (0 when absent).
inline double PrintedValue(vtkObject* object, const std::string& label)
{
  std::ostringstream os;
  object->Print(os);
  const std::string text = os.str();
  const std::size_t at = text.find(label);
  return at == std::string::npos ? 0.0 : std::atof(text.c_str() + at + label.size());
}

struct Bench
{
  /// Our mappers' EmptySpaceSkipping (--no-skipping turns it off, to measure what it buys).
  bool SkipEmptySpace = true;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkImageData> Volume;
  std::vector<vtkSmartPointer<vtkLight>> Lights;
  int Frames = 10;

  double Frame()
  {
    const auto start = std::chrono::steady_clock::now();
    this->Window->Render();
    this->Window->WaitForCompletion();
    return Seconds(start);
  }

  void SetLights(int count)
  {
    this->Renderer->RemoveAllLights();
    for (int i = 0; i < count && i < static_cast<int>(this->Lights.size()); ++i)
    {
      this->Renderer->AddLight(this->Lights[i]);
    }
  }

  /// Volumes of `mappers` with the bench's property, in the renderer.
  std::vector<vtkSmartPointer<vtkVolume>> AddVolumes(const std::vector<vtkVolumeMapper*>& mappers)
  {
    std::vector<vtkSmartPointer<vtkVolume>> volumes;
    for (vtkVolumeMapper* mapper : mappers)
    {
      volumes.push_back(vtkSmartPointer<vtkVolume>::New());
      volumes.back()->SetMapper(mapper);
      volumes.back()->SetProperty(this->Property);
      this->Renderer->AddVolume(volumes.back());
    }
    return volumes;
  }
  void RemoveVolumes(const std::vector<vtkSmartPointer<vtkVolume>>& volumes)
  {
    for (vtkVolume* volume : volumes)
    {
      this->Renderer->RemoveVolume(volume);
    }
  }
  /// The frame time with volumes[shown] alone visible.
  double FrameOf(const std::vector<vtkSmartPointer<vtkVolume>>& volumes, std::size_t shown)
  {
    for (std::size_t v = 0; v < volumes.size(); ++v)
    {
      volumes[v]->SetVisibility(v == shown);
    }
    return this->Frame();
  }

  /// Each mapper's warm-up frame time, then the median over Frames frames with a moving camera
  /// (and the frames themselves). With several mappers their frames alternate at each camera
  /// position, so that a machine whose speed drifts slows all alike.
  struct Timing
  {
    double First = 0.0, Median = 0.0;
    std::vector<double> Frames;
  };
  std::vector<Timing> MeasureEach(const std::vector<vtkVolumeMapper*>& mappers)
  {
    const auto volumes = this->AddVolumes(mappers);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.5, 0.7, 4.2);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    this->Renderer->ResetCameraClippingRange();
    std::vector<Timing> timings(mappers.size());
    for (std::size_t m = 0; m < mappers.size(); ++m)
    {
      timings[m].First = this->FrameOf(volumes, m);
    }
    for (int f = 0; f < this->Frames; ++f)
    {
      camera->Azimuth(3.0);
      this->Renderer->ResetCameraClippingRange();
      for (std::size_t m = 0; m < mappers.size(); ++m)
      {
        timings[m].Frames.push_back(this->FrameOf(volumes, m));
      }
    }
    this->RemoveVolumes(volumes);
    for (Timing& t : timings)
    {
      t.Median = Median(t.Frames);
    }
    return timings;
  }

  /// The median over the camera positions of b's frame over a's (MeasureEach's frames at the
  /// same positions).
  static double RatioOf(const Timing& a, const Timing& b)
  {
    std::vector<double> ratios;
    for (std::size_t f = 0; f < a.Frames.size() && f < b.Frames.size(); ++f)
    {
      ratios.push_back(b.Frames[f] / a.Frames[f]);
    }
    return ratios.empty() ? 0.0 : Median(ratios);
  }

  struct Interaction
  {
    double Interactive = 0.0; ///< median interactive frame
    double Still = 0.0;       ///< the still frame after the interaction
    /// Ours: the last interactive image sample distance; VTK's: the last interactive reduction
    /// factor of its ray step (its PrintSelf's ReductionFactor; the step is divided by it).
    double Distance = 1.0;
    int RebuildsInteracting = 0, RebuildsAtStill = 0; ///< ours: light-volume rebuilds
  };

  /// A still frame, Frames interactive frames at desired update rate 15 with a moving camera,
  /// and the still frame after them.
  Interaction Interact(vtkVolumeMapper* mapper, vtkVolumeProperty* property)
  {
    constexpr double interactiveRate = 15.0, stillRate = 0.0001; // the interactor's defaults
    auto* ours = vtkAVSVolumeMapper::SafeDownCast(mapper);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    this->Renderer->AddVolume(volume);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.5, 0.7, 4.2);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    this->Renderer->ResetCameraClippingRange();
    this->Window->SetDesiredUpdateRate(stillRate);
    this->Frame();
    const int before = ours ? ours->GetNumberOfLightVolumeRebuilds() : 0;
    this->Window->SetDesiredUpdateRate(interactiveRate);
    std::vector<double> times;
    for (int f = 0; f < this->Frames; ++f)
    {
      camera->Azimuth(3.0);
      this->Renderer->ResetCameraClippingRange();
      times.push_back(this->Frame());
    }
    Interaction out;
    out.Interactive = Median(times);
    out.Distance =
      ours ? ours->GetLastImageSampleDistance() : PrintedValue(mapper, "ReductionFactor: ");
    const int interacting = ours ? ours->GetNumberOfLightVolumeRebuilds() : 0;
    this->Window->SetDesiredUpdateRate(stillRate);
    out.Still = this->Frame();
    out.RebuildsInteracting = interacting - before;
    out.RebuildsAtStill = (ours ? ours->GetNumberOfLightVolumeRebuilds() : 0) - interacting;
    this->Renderer->RemoveVolume(volume);
    return out;
  }

  void SetHeadlight()
  {
    this->Renderer->RemoveAllLights();
    vtkNew<vtkLight> light;
    light->SetLightTypeToHeadlight();
    light->SetIntensity(5.0);
    this->Renderer->AddLight(light);
  }

  void SetLightKit()
  {
    this->Renderer->RemoveAllLights();
    vtkNew<vtkLightKit> kit;
    kit->SetKeyLightIntensity(5.0);
    kit->AddLightsToRenderer(this->Renderer);
  }
};

#endif
