// avs-bench-mappers' interaction scenario (see the top of avs-bench-mappers.cxx): VTK's mapper
// shaded and ours under the interactor's desired update rates, with a headlight and a light kit.
#ifndef avs_BenchInteraction_h
#define avs_BenchInteraction_h

#include "MapperBench.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

/// The interaction scenario (see the top of avs-bench-mappers.cxx); false when the light-volume
/// rebuilds were not the expected ones (none while interacting, the stale ones at the still frame).
inline bool RunInteraction(Bench& b, int lightGrid, const std::string& scene)
{
  vtkNew<vtkVolumeProperty> shaded;
  shaded->DeepCopy(b.Property);
  shaded->ShadeOn();
  std::printf("# interaction: desired update rate 15 (one renderer, one volume: %.4f s allotted), "
              "%d frames turning 3 degrees, then a still frame; VTK's mapper shaded; "
              "AutoAdjustSampleDistances on for all\n",
    1.0 / 15.0,
    b.Frames);
  bool ok = true;
  for (const std::string lights : { "headlight", "lightkit" })
  {
    const std::string suffix = "_" + lights + scene;
    if (lights == "headlight")
    {
      b.SetHeadlight();
    }
    else
    {
      b.SetLightKit();
    }
    vtkNew<vtkGPUVolumeRayCastMapper> vtkShaded;
    vtkShaded->SetInputData(b.Volume);
    vtkShaded->SetUseJittering(0);
    const auto v = b.Interact(vtkShaded, shaded);
    std::printf("bench interactive_frame_vtk_shaded%s %.4f s\n", suffix.c_str(), v.Interactive);
    std::printf("bench still_frame_vtk_shaded%s %.4f s\n", suffix.c_str(), v.Still);
    std::printf("bench reduction_factor_vtk_shaded%s %.2f\n", suffix.c_str(), v.Distance);

    std::vector<std::pair<std::string, vtkSmartPointer<vtkAVSVolumeMapper>>> ours;
    if (lights == "headlight") // EA and AO do not use the lights
    {
      ours.emplace_back("ea", vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New());
      ours.emplace_back("ao", vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New());
    }
    // Ambient scattering at VTK's default range of image sample distances, at most 4, and (with
    // the light kit) without adjustment: every frame exact, every camera light rebuilt.
    for (const float most : { 10.0f, 4.0f, 0.0f })
    {
      if (most == 0.0f && lights == "headlight")
      {
        continue;
      }
      auto as = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
      if (lightGrid > 0)
      {
        as->SetLightVolumeMaximumDimension(lightGrid);
      }
      if (most > 0.0f)
      {
        as->SetMaximumImageSampleDistance(most);
      }
      else
      {
        as->AutoAdjustSampleDistancesOff();
      }
      ours.emplace_back(most == 10.0f ? "as" : (most == 4.0f ? "as_max4" : "as_fixed"), as);
    }
    for (auto& [name, mapper] : ours)
    {
      mapper->SetInputData(b.Volume);
      mapper->SetSampleDistance(0.5 * b.Volume->GetSpacing()[0]);
      mapper->UseJitteringOff();
      mapper->SetEmptySpaceSkipping(b.SkipEmptySpace);
      const auto o = b.Interact(mapper, b.Property);
      const bool scattering = name.rfind("as", 0) == 0;
      const std::string label = name + (scattering ? suffix : scene);
      std::printf("bench interactive_frame_%s %.4f s\n", label.c_str(), o.Interactive);
      std::printf("bench still_frame_%s %.4f s\n", label.c_str(), o.Still);
      std::printf("bench image_sample_distance_%s %.1f\n", label.c_str(), o.Distance);
      if (scattering)
      {
        const bool fixed = name == "as_fixed";
        const int expected = lights == "headlight" ? 1 : (fixed ? 0 : 5);
        std::printf(
          "bench light_volume_rebuilds_interactive_%s %d\n", label.c_str(), o.RebuildsInteracting);
        std::printf("bench light_volume_rebuilds_still_%s %d\n", label.c_str(), o.RebuildsAtStill);
        ok = ok && o.RebuildsInteracting == (fixed ? 5 * b.Frames : 0) &&
          o.RebuildsAtStill == expected;
        std::printf("ratio interactive_%s_over_vtk_shaded%s %.3f\n",
          label.c_str(),
          suffix.c_str(),
          o.Interactive / v.Interactive);
      }
    }
  }
  return ok;
}

#endif
