// avs-bench-mappers --time-series: a simulation played step by step, the camera still. Each step
// is the bench's volume moved along x by a few voxels (wrapping round, so that every voxel
// changes and the structure travels through the box) in the same vtkImageData, its scalars
// modified in place as a time-varying source modifies them; each mapper renders the step alone,
// in alternation, and the step's time runs from the new data to the finished frame (the upload
// and, for ambient scattering, the averaged extinction, the light volumes and the extended
// model's diffusion included). With one light: VTK's mapper unshaded and shaded, our EA and
// ambient scattering in the paper's model (as) and the extended one (asx); with four lights:
// VTK's shaded, as4 and asx4. Reported: each mapper's median step after the first (which
// compiles the programs and allocates), and the median over the steps of the per-step ratios.
// Then our mappers' steps again with StageTiming on (the GPU finished after each stage), the
// median of each stage over the steps: where a step's time goes
// ("bench timestep_stage_MAPPER_STAGE", stages as vtkAVSVolumeMapper::RenderStage names them).
#ifndef avs_BenchTimeSeries_h
#define avs_BenchTimeSeries_h

#include "MapperBench.h"

#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkDataArray.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPointData.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

/// `source` moved `shift` voxels along x into `out` (the same type, size and components, standard
/// memory layout): each row rotated, out[x] = source[x - shift], wrapping round.
inline void MoveAlongX(vtkDataArray* source, vtkDataArray* out, const int dimensions[3], int shift)
{
  const int nx = dimensions[0];
  const std::size_t texel =
    static_cast<std::size_t>(source->GetDataTypeSize()) * source->GetNumberOfComponents();
  const std::size_t row = texel * nx;
  const std::size_t rows = static_cast<std::size_t>(dimensions[1]) * dimensions[2];
  const int s = ((shift % nx) + nx) % nx;
  const char* from = static_cast<const char*>(source->GetVoidPointer(0));
  char* to = static_cast<char*>(out->GetVoidPointer(0));
  for (std::size_t r = 0; r < rows; ++r)
  {
    // to[x] = from[x - s]
    std::memcpy(to + r * row + texel * s, from + r * row, texel * (nx - s));
    std::memcpy(to + r * row, from + r * row + texel * (nx - s), texel * s);
  }
}

/// The time-series scenario; `steps` steps (at least 3), the lines' names ending in `scene`.
/// False when one of our mappers did not upload the data at every step.
inline bool RunTimeSeries(Bench& b, int steps, const std::string& scene)
{
  bool uploadedEveryStep = true;
  steps = std::max(3, steps);
  constexpr int voxelsPerStep = 3;
  vtkDataArray* original = b.Volume->GetPointData()->GetScalars();
  int dimensions[3];
  b.Volume->GetDimensions(dimensions);
  // The series' volume: the bench's geometry with scalars of its own, rewritten at every step.
  vtkNew<vtkImageData> series;
  series->CopyStructure(b.Volume);
  vtkSmartPointer<vtkDataArray> values;
  values.TakeReference(original->NewInstance());
  values->DeepCopy(original);
  values->SetName("density");
  series->GetPointData()->SetScalars(values);

  vtkNew<vtkVolumeProperty> shaded;
  shaded->DeepCopy(b.Property);
  shaded->ShadeOn();
  const double sampleDistance = 0.5 * b.Volume->GetSpacing()[0];
  auto vtkMapper = [&]()
  {
    auto m = vtkSmartPointer<vtkGPUVolumeRayCastMapper>::New();
    m->SetInputData(series);
    m->SetAutoAdjustSampleDistances(0);
    m->SetSampleDistance(sampleDistance);
    m->SetUseJittering(0);
    return m;
  };
  auto ours = [&](vtkAVSVolumeMapper* m)
  {
    m->SetInputData(series);
    m->SetSampleDistance(sampleDistance);
    m->UseJitteringOff();
    m->SetEmptySpaceSkipping(b.SkipEmptySpace);
  };
  auto scattering = [&](bool extended)
  {
    auto m = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
    if (extended)
      m->SetScatteringModelToExtended();
    else
      m->SetScatteringModelToPaper();
    ours(m);
    return m;
  };
  vtkCamera* camera = b.Renderer->GetActiveCamera();
  camera->SetPosition(0.5, 0.7, 4.2);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  b.Renderer->ResetCameraClippingRange();
  std::printf("# time series: %d steps, the volume moved %d voxels along x per step, camera "
              "still; per step from the new data to the finished frame\n",
    steps,
    voxelsPerStep);

  // One group of mappers with `lights` lights: each step's time per mapper (steps after the
  // first), and for ours with StageTiming on each stage's time per step.
  struct Played
  {
    std::vector<std::vector<double>> Steps;               ///< [mapper][step]
    std::vector<std::vector<std::vector<double>>> Stages; ///< [mapper][stage][step]
  };
  auto play = [&](int lights,
                const std::vector<vtkVolumeMapper*>& mappers,
                const std::vector<vtkVolumeProperty*>& properties)
  {
    Played played;
    played.Steps.resize(mappers.size());
    played.Stages.assign(
      mappers.size(), std::vector<std::vector<double>>(vtkAVSVolumeMapper::NumberOfRenderStages));
    b.SetLights(lights);
    std::vector<vtkSmartPointer<vtkVolume>> volumes;
    for (std::size_t m = 0; m < mappers.size(); ++m)
    {
      volumes.push_back(vtkSmartPointer<vtkVolume>::New());
      volumes.back()->SetMapper(mappers[m]);
      volumes.back()->SetProperty(properties[m]);
      b.Renderer->AddVolume(volumes.back());
    }
    std::vector<int> uploadsBefore;
    for (vtkVolumeMapper* m : mappers)
    {
      auto* mine = vtkAVSVolumeMapper::SafeDownCast(m);
      uploadsBefore.push_back(mine ? mine->GetNumberOfDataUploads() : 0);
    }
    for (int step = 0; step < steps; ++step)
    {
      MoveAlongX(original, values, dimensions, step * voxelsPerStep);
      values->Modified();
      series->Modified();
      for (std::size_t m = 0; m < mappers.size(); ++m)
      {
        const double t = b.FrameOf(volumes, m);
        auto* mine = vtkAVSVolumeMapper::SafeDownCast(mappers[m]);
        if (step > 0)
        {
          played.Steps[m].push_back(t);
          const bool timed = mine && mine->GetStageTiming();
          for (int stage = 0; timed && stage < vtkAVSVolumeMapper::NumberOfRenderStages; ++stage)
          {
            played.Stages[m][static_cast<std::size_t>(stage)].push_back(
              mine->GetLastStageSeconds(stage));
          }
        }
      }
    }
    b.RemoveVolumes(volumes);
    // Each of ours uploaded every step (else the series measured nothing new).
    for (std::size_t m = 0; m < mappers.size(); ++m)
    {
      auto* mine = vtkAVSVolumeMapper::SafeDownCast(mappers[m]);
      uploadedEveryStep =
        uploadedEveryStep && (!mine || mine->GetNumberOfDataUploads() - uploadsBefore[m] == steps);
    }
    return played;
  };
  auto medianRatio = [](const std::vector<double>& over, const std::vector<double>& under)
  {
    std::vector<double> r;
    for (std::size_t s = 0; s < over.size() && s < under.size(); ++s)
    {
      r.push_back(over[s] / under[s]);
    }
    return r.empty() ? 0.0 : Median(r);
  };
  auto name = [&scene](const std::string& n) { return n + scene; };

  auto vtkEA = vtkMapper();
  auto vtkShaded = vtkMapper();
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  ours(ea);
  auto as = scattering(false), asx = scattering(true);
  const auto one = play(1,
    { vtkEA, vtkShaded, ea, as, asx },
    { b.Property, shaded, b.Property, b.Property, b.Property });
  const char* oneNames[5] = { "vtk_ea", "vtk_shaded", "ea", "as", "asx" };
  for (int m = 0; m < 5; ++m)
  {
    std::printf("bench %s %.4f s\n",
      name(std::string("timestep_") + oneNames[m]).c_str(),
      Median(one.Steps[static_cast<std::size_t>(m)]));
  }
  auto vtkShaded4 = vtkMapper();
  auto as4 = scattering(false), asx4 = scattering(true);
  const auto four = play(4, { vtkShaded4, as4, asx4 }, { shaded, b.Property, b.Property });
  const char* fourNames[3] = { "vtk_shaded4", "as4", "asx4" };
  for (int m = 0; m < 3; ++m)
  {
    std::printf("bench %s %.4f s\n",
      name(std::string("timestep_") + fourNames[m]).c_str(),
      Median(four.Steps[static_cast<std::size_t>(m)]));
  }
  std::printf("ratio %s %.3f\n",
    name("timestep_ea_over_vtk_ea").c_str(),
    medianRatio(one.Steps[2], one.Steps[0]));
  std::printf("ratio %s %.3f\n",
    name("timestep_as_over_vtk_shaded").c_str(),
    medianRatio(one.Steps[3], one.Steps[1]));
  std::printf("ratio %s %.3f\n",
    name("timestep_asx_over_vtk_shaded").c_str(),
    medianRatio(one.Steps[4], one.Steps[1]));
  std::printf("ratio %s %.3f\n",
    name("timestep_as4_over_vtk_shaded").c_str(),
    medianRatio(four.Steps[1], four.Steps[0]));
  std::printf("ratio %s %.3f\n",
    name("timestep_asx4_over_vtk_shaded").c_str(),
    medianRatio(four.Steps[2], four.Steps[0]));

  // The breakdown: our mappers again, each stage timed (the GPU finished after each).
  auto breakdown = [&](int lights,
                     const std::vector<vtkAVSVolumeMapper*>& mappers,
                     const std::vector<std::string>& names)
  {
    std::vector<vtkVolumeMapper*> timed;
    std::vector<vtkVolumeProperty*> properties;
    for (vtkAVSVolumeMapper* m : mappers)
    {
      m->StageTimingOn();
      timed.push_back(m);
      properties.push_back(b.Property);
    }
    const Played played = play(lights, timed, properties);
    for (std::size_t m = 0; m < mappers.size(); ++m)
    {
      mappers[m]->StageTimingOff();
      for (int stage = 0; stage < vtkAVSVolumeMapper::NumberOfRenderStages; ++stage)
      {
        std::printf("bench %s %.4f s\n",
          name("timestep_stage_" + names[m] + "_" + vtkAVSVolumeMapper::GetRenderStageName(stage))
            .c_str(),
          Median(played.Stages[m][static_cast<std::size_t>(stage)]));
      }
      std::printf(
        "bench %s %.4f s\n", name("timestep_timed_" + names[m]).c_str(), Median(played.Steps[m]));
    }
  };
  std::printf("# the steps' breakdown: each stage's median, the GPU finished after each "
              "(timestep_timed_*: the whole step so timed)\n");
  breakdown(1, { ea, as, asx }, { "ea", "as", "asx" });
  breakdown(4, { as4, asx4 }, { "as4", "asx4" });
  return uploadedEveryStep;
}

#endif
