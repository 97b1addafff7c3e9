// avs-accuracy: how far EA, AO and ambient scattering are from the truth (the path tracer) on
// scenes where scattering matters. Prints one line per scene and model:
//
//   accuracy <scene> <ea|ao|as> rmse=<x> rel_l1=<y>
//
// and writes a picture: per scene (bottom to top) truth | EA | AO | AS | 4x |EA - truth| |
// 4x |AO - truth| | 4x |AS - truth|, all on one exposure. See AccuracyStudy.h for how EA and AO
// are made comparable.
#include "AccuracyStudy.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

int main(int argc, char* argv[])
{
  AccuracySettings settings;
  settings.OutputPicture = "accuracy.png";
  settings.Verbose = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::printf(
        "Usage: avs-accuracy [--size N] [--voxels N] [--spp N] [--output FILE.png]\n"
        "                    [--scenes A,B,...] [--cloud-opacity X] [--ambient-radius R]\n"
        "                    [--shade B]\n"
        "\n"
        "Renders four scenes (cloud_back, cloud_side, nebula_point, dense_medical) with the GPU\n"
        "EA, AO and ambient-scattering mappers and with the path tracer, and prints each\n"
        "mapper's error.\n"
        "  --scenes          some of the scenes, comma-separated; also plume_point (a point\n"
        "                    light with VTK's default attenuation inside the cloud)\n"
        "  --cloud-opacity   opacity of the clouds' densest scalar, in (0, 1]; their optical\n"
        "                    thickness scales with -ln(1 - X)\n"
        "  --ambient-radius  the ambient-scattering mapper's AmbientRadius and the AO mapper's\n"
        "                    OcclusionRadius (world units; the scenes span [-1, 1]^3; 0: their\n"
        "                    default, 1/64 of the diagonal)\n"
        "  --truth-cache     a folder that keeps the path tracer's pictures between runs\n"
        "  --shade B         surfaces inside the medium: ShadeOn with "
        "VolumetricScatteringBlending\n"
        "                    B (0-2) in the truth and ambient scattering, and two more models:\n"
        "                    asx_off (ShadeOff) and vtk (VTK's shaded mapper, best exposure)\n"
        "Defaults: --size 96 --voxels 64 --spp 512 --output accuracy.png --cloud-opacity 0.6\n"
        "--ambient-radius 0\n");
      return 0;
    }
    if (i + 1 >= argc)
    {
      std::fprintf(stderr, "avs-accuracy: %s needs a value\n", arg.c_str());
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--size")
      settings.ImageSize = std::max(8, std::atoi(value.c_str()));
    else if (arg == "--voxels")
      settings.Voxels = std::max(8, std::atoi(value.c_str()));
    else if (arg == "--spp")
      settings.SamplesPerPixel = std::max(1, std::atoi(value.c_str()));
    else if (arg == "--output")
      settings.OutputPicture = value;
    else if (arg == "--shade")
    {
      settings.Shade = true;
      settings.Blending = std::clamp(std::atof(value.c_str()), 0.0, 2.0);
    }
    else if (arg == "--scenes")
    {
      settings.Scenes.clear();
      std::stringstream list(value);
      for (std::string scene; std::getline(list, scene, ',');)
      {
        settings.Scenes.push_back(scene);
      }
    }
    else if (arg == "--cloud-opacity")
      settings.CloudOpacity = std::atof(value.c_str());
    else if (arg == "--truth-cache")
      settings.TruthCache = value;
    else if (arg == "--ambient-radius")
      settings.AmbientRadius = std::atof(value.c_str());
    else
    {
      std::fprintf(stderr, "avs-accuracy: unknown option %s\n", arg.c_str());
      return 2;
    }
  }
  std::vector<AccuracyResult> results;
  double noise = 0.0;
  if (!RunAccuracyStudy(settings, results, &noise))
  {
    return 1;
  }
  for (const auto& r : results)
  {
    std::printf("accuracy %s %s rmse=%.4f rel_l1=%.4f mean/truth=%.3f\n",
      r.Scene.c_str(),
      r.Model.c_str(),
      r.Rmse,
      r.RelativeL1,
      r.MeanRatio);
  }
  std::printf("# path-tracer noise (RMSE of the truth itself, worst scene): %.4f\n", noise);
  std::printf("# picture: %s\n", settings.OutputPicture.c_str());
  return 0;
}
