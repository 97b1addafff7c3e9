// avs-bench-mappers: frame times of the GPU mappers side by side with VTK's own
// vtkGPUVolumeRayCastMapper, in one run, on one scene, as ratios:
//
//   bench <name> <value> <unit>
//   ratio <name> <value>
//
// Scene: the built-in nebula (default 256^3) or, with --embryo FILE, the real embryo scan (VTK's
// embryo.slc, 256^3 unsigned 8-bit, most of it empty), placed in the nebula's box with the
// nebula's transfer functions over its own range, 512 x 512 pixels, the same sample distance
// (half a voxel) and transfer functions for every mapper, jittering off. The embryo's lines
// carry the suffix _embryo. Each mapper renders a warm-up frame (which
// includes its precomputation), then frames with a camera turning 3 degrees per frame; the
// median of their times is reported. The mappers render in alternation, frame by frame at each
// camera position (with one light VTK's EA, ours, AO and ambient scattering in both models, the
// paper's, as1, and the extended one, asx1; with four lights our EA and ambient scattering in
// both models, as4 and asx4), and each ratio is the median of the per-position ratios, so that the
// ratios do not follow the machine's drifts (--frames-only stops after them). Then the rebuild
// after a transfer-function change and after a light move, for both models in alternation: the
// frame after the change less the next frame, the median over five changes of each kind.
//
// Then interaction (BenchInteraction.h), as vtkRenderWindowInteractor drives it (its style sets the
// render window's desired update rate to the interactor's DesiredUpdateRate, 15, while a button is
// down, and to its StillUpdateRate, 0.0001, at the release): a still frame, 10 frames turning 3
// degrees at rate 15, and the still frame after them, for VTK's mapper shaded with its own
// adjustment (AutoAdjustSampleDistances on) and ours (AutoAdjustSampleDistances on; ambient
// scattering also with MaximumImageSampleDistance 4, "as_max4", and with the light kit also without
// adjustment, "as_fixed", every frame exact as before the adjustment existed), with a headlight and
// with a light kit (five lights that follow the camera). Reported: the median interactive frame,
// the still frame after the interaction, the image sample distance ours settled on (VTK's reduction
// factor of its ray step), and the light-volume rebuilds during and after it (checked: none
// while interacting, the stale ones at the still frame). --interaction-only runs this part alone.
//
// --clipping gives every mapper (VTK's too) three clipping planes and cropping (the fence
// preset); --clipping-nothing the same tests with planes outside the volume and every cropping
// region kept (the picture of a run without clipping), so that a run with it against one
// without says what the clipping tests cost per frame. --scattering-models-only measures the two
// ambient-scattering models alone (as4 and asx4: frames, rebuilds and their ratios).
// --no-skipping turns our mappers' empty-space skipping off (what it buys: a run with it
// against one without). --time-series plays the volume as a simulation of --steps steps instead
// (BenchTimeSeries.h). --shade measures what surfaces inside the medium cost: the extended
// model's frame with ShadeOn (VolumetricScatteringBlending 0) against the unshaded one (ShadeOn
// with blending 2 builds the unshaded program, ShadeOff's bit for bit), with one light and with
// four, in alternation (shade_over_unshaded, shade4_over_unshaded4), and stops.
#include "BenchInteraction.h"
#include "BenchScene.h"
#include "BenchTimeSeries.h"
#include "MapperBench.h"
#include "ProceduralVolume.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSLCReader.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataWriter.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

int main(int argc, char* argv[])
{
  int voxels = 256, size = 512, frames = 10, lightGrid = 0, steps = 20;
  bool skipEmptySpace = true, timeSeries = false, interactionOnly = false, clipping = false,
       clipNothing = false, modelsOnly = false, framesOnly = false, shadeOnly = false;
  std::string writeScene, embryo;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      std::printf(
        "Usage: avs-bench-mappers [--voxels N] [--size N] [--frames N] [--light-grid N] "
        "[--interaction-only | --scattering-models-only] [--frames-only] "
        "[--clipping | --clipping-nothing] "
        "[--write-scene FILE.vti] [--embryo FILE.slc] [--no-skipping] "
        "[--time-series [--steps N]] [--shade]\n\n"
        "Median frame times of VTK's vtkGPUVolumeRayCastMapper and of the module's "
        "mappers on the built-in nebula\n(N^3 voxels, default 256), N x N pixels "
        "(default 512), over N frames (default 10), and their ratios;\nthen interactive "
        "frames (desired update rate 15) with a headlight and with a light kit.\n"
        "--light-grid sets the ambient-scattering mappers' LightVolumeMaximumDimension "
        "(default: the mappers' own default).\n"
        "--interaction-only runs the interaction scenario alone.\n"
        "--scattering-models-only measures ambient scattering with 4 lights in the paper's "
        "and the extended model alone.\n"
        "--frames-only: the frames and their ratios alone (no rebuilds, no interaction).\n"
        "--shade: the extended model's frame with ShadeOn (surfaces inside the medium) "
        "against ShadeOff's, one light and four, and stop.\n"
        "--clipping: three clipping planes and cropping (fence) on every mapper;\n"
        "--clipping-nothing: planes outside the volume, every cropping region kept.\n"
        "--write-scene FILE.vti: write the nebula (for ParaView's peer, "
        "Utilities/ParaView) and stop.\n"
        "--embryo FILE.slc: the embryo scan (VTK's embryo.slc) in place of the nebula; its "
        "lines end in _embryo.\n"
        "--no-skipping: our mappers march through empty space (EmptySpaceSkipping off).\n"
        "--time-series: N steps (default 20) of the volume moving, camera still, each from the "
        "new data to the finished frame (BenchTimeSeries.h), and stop.\n");
      return 0;
    }
    if (arg == "--write-scene" && i + 1 < argc)
    {
      writeScene = argv[++i];
      continue;
    }
    if (arg == "--embryo" && i + 1 < argc)
    {
      embryo = argv[++i];
      continue;
    }
    if (arg == "--interaction-only")
    {
      interactionOnly = true;
      continue;
    }
    if (arg == "--time-series")
    {
      timeSeries = true;
      continue;
    }
    if (arg == "--no-skipping")
    {
      skipEmptySpace = false;
      continue;
    }
    if (arg == "--shade")
    {
      shadeOnly = true;
      continue;
    }
    if (arg == "--frames-only")
    {
      framesOnly = true;
      continue;
    }
    if (arg == "--scattering-models-only")
    {
      modelsOnly = true;
      continue;
    }
    if (arg == "--clipping" || arg == "--clipping-nothing")
    {
      clipping = true;
      clipNothing = arg == "--clipping-nothing";
      continue;
    }
    if (i + 1 < argc &&
      (arg == "--voxels" || arg == "--size" || arg == "--frames" || arg == "--light-grid" ||
        arg == "--steps"))
    {
      const int v = std::max(2, std::atoi(argv[++i]));
      if (arg == "--voxels")
        voxels = v;
      else if (arg == "--size")
        size = v;
      else if (arg == "--frames")
        frames = v;
      else if (arg == "--steps")
        steps = v;
      else
        lightGrid = v;
    }
  }

  Bench b;
  b.Frames = frames;
  b.SkipEmptySpace = skipEmptySpace;
  std::string scene = "nebula";
  double top = 1.0; // the transfer functions' scalar range is [0, top]
  if (!embryo.empty())
  {
    // The scan in the nebula's box [-1, 1]^3, so that the camera, the lights and the unit
    // distance are the nebula's.
    vtkNew<vtkSLCReader> reader;
    reader->SetFileName(embryo.c_str());
    reader->Update();
    vtkImageData* scan = reader->GetOutput();
    int d[3];
    scan->GetDimensions(d);
    if (reader->GetErrorCode() != 0 || !scan->GetPointData()->GetScalars() || d[0] < 2 ||
      d[1] < 2 || d[2] < 2)
    {
      std::fprintf(stderr, "avs-bench-mappers: cannot read the scan %s\n", embryo.c_str());
      return 1;
    }
    b.Volume->ShallowCopy(scan);
    const int longest = std::max({ d[0], d[1], d[2] });
    const double h = 2.0 / (longest - 1);
    b.Volume->SetSpacing(h, h, h);
    b.Volume->SetOrigin(-0.5 * h * (d[0] - 1), -0.5 * h * (d[1] - 1), -0.5 * h * (d[2] - 1));
    top = b.Volume->GetPointData()->GetScalars()->GetRange()[1];
    scene = "embryo";
    voxels = longest;
  }
  else
  {
    const avs::Grid nebula = avs::MakeNebula(voxels);
    const auto& g = nebula.Geometry;
    b.Volume->SetDimensions(g.Dimensions[0], g.Dimensions[1], g.Dimensions[2]);
    b.Volume->SetSpacing(g.Spacing.x, g.Spacing.y, g.Spacing.z);
    b.Volume->SetOrigin(g.Origin.x, g.Origin.y, g.Origin.z);
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfTuples(static_cast<vtkIdType>(nebula.Values.size()));
    std::copy(nebula.Values.begin(), nebula.Values.end(), values->GetPointer(0));
    values->SetName("density");
    b.Volume->GetPointData()->SetScalars(values);
  }
  // The embryo's lines carry its name.
  const std::string suffix = scene == "nebula" ? "" : "_" + scene;
  auto name = [&suffix](const char* n) { return std::string(n) + suffix; };
  if (!writeScene.empty())
  {
    // The same volume for the ParaView peer (Utilities/ParaView/avs-bench-paraview.py), which
    // sets the transfer functions, lights, sample distance and image size below itself.
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(writeScene.c_str());
    writer->SetInputData(b.Volume);
    if (!writer->Write())
    {
      std::fprintf(stderr, "avs-bench-mappers: cannot write %s\n", writeScene.c_str());
      return 1;
    }
    std::printf("# scene: %s %d^3 written to %s\n", scene.c_str(), voxels, writeScene.c_str());
    return 0;
  }

  vtkNew<vtkColorTransferFunction> color;
  ConfigureBenchProperty(b.Property, color, b.Opacity, top);
  b.Lights = MakeBenchLights();

  b.Window->SetSize(size, size);
  b.Window->SetMultiSamples(0);
  b.Window->OffScreenRenderingOn();
  b.Window->AddRenderer(b.Renderer);
  b.SetLights(1);

  const double sampleDistance = 0.5 * b.Volume->GetSpacing()[0];
  std::printf("# scene: %s %d^3, %d x %d pixels, sample distance %g, %d frames per mapper, "
              "light volumes at most %d per axis, empty-space skipping %s\n",
    scene.c_str(),
    voxels,
    size,
    size,
    sampleDistance,
    frames,
    lightGrid > 0
      ? lightGrid
      : vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New()->GetLightVolumeMaximumDimension(),
    b.SkipEmptySpace ? "on" : "off");

  if (timeSeries)
  {
    if (!RunTimeSeries(b, steps, suffix))
    {
      std::fprintf(stderr, "avs-bench-mappers: a mapper did not upload every step's data\n");
      return 1;
    }
    return 0;
  }
  if (interactionOnly)
  {
    if (!RunInteraction(b, lightGrid, suffix))
    {
      std::fprintf(stderr, "avs-bench-mappers: light volumes were rebuilt while interacting\n");
      return 1;
    }
    return 0;
  }

  vtkNew<vtkGPUVolumeRayCastMapper> vtkEA;
  vtkEA->SetInputData(b.Volume);
  vtkEA->SetAutoAdjustSampleDistances(0);
  vtkEA->SetSampleDistance(sampleDistance);
  vtkEA->SetUseJittering(0);
  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as1;
  vtkNew<vtkAmbientScatteringVolumeMapper> asx1; // the extended model (the default)
  vtkNew<vtkAmbientScatteringVolumeMapper> as4;
  vtkNew<vtkAmbientScatteringVolumeMapper> asx4; // the extended model (the default)
  asx4->SetScatteringModelToExtended();
  asx1->SetScatteringModelToExtended();
  as1->SetScatteringModelToPaper(); // the paper's model, which the frame targets are set for
  as4->SetScatteringModelToPaper();
  if (lightGrid > 0)
  {
    as1->SetLightVolumeMaximumDimension(lightGrid);
    asx1->SetLightVolumeMaximumDimension(lightGrid);
    as4->SetLightVolumeMaximumDimension(lightGrid);
    asx4->SetLightVolumeMaximumDimension(lightGrid);
  }
  for (vtkAVSVolumeMapper* m : { static_cast<vtkAVSVolumeMapper*>(ea),
         static_cast<vtkAVSVolumeMapper*>(ao),
         static_cast<vtkAVSVolumeMapper*>(as1),
         static_cast<vtkAVSVolumeMapper*>(asx1),
         static_cast<vtkAVSVolumeMapper*>(as4),
         static_cast<vtkAVSVolumeMapper*>(asx4) })
  {
    m->SetInputData(b.Volume);
    m->SetSampleDistance(sampleDistance);
    m->UseJitteringOff();
    m->SetEmptySpaceSkipping(b.SkipEmptySpace);
  }
  if (clipping)
  {
    const double planes[3][6] = {
      { 0.4, 0, 0, -1, 0.2, 0.1 }, { 0, -0.5, 0, 0.1, 1, 0.2 }, { 0, 0, 0.5, 0.2, -0.1, -1 }
    };
    for (vtkVolumeMapper* m : { static_cast<vtkVolumeMapper*>(vtkEA),
           static_cast<vtkVolumeMapper*>(ea),
           static_cast<vtkVolumeMapper*>(ao),
           static_cast<vtkVolumeMapper*>(as1),
           static_cast<vtkVolumeMapper*>(asx1),
           static_cast<vtkVolumeMapper*>(as4),
           static_cast<vtkVolumeMapper*>(asx4) })
    {
      for (const auto& p : planes)
      {
        vtkNew<vtkPlane> plane;
        // Moved 3 units back along the normal, outside the volume box: nothing is cut.
        const double back = clipNothing ? -3.0 : 0.0;
        plane->SetOrigin(p[0] + back * p[3], p[1] + back * p[4], p[2] + back * p[5]);
        plane->SetNormal(p[3], p[4], p[5]);
        m->AddClippingPlane(plane);
      }
      m->CroppingOn();
      m->SetCroppingRegionPlanes(-0.3, 0.3, -0.3, 0.3, -0.3, 0.3);
      m->SetCroppingRegionFlags(clipNothing ? 0x7ffffff : VTK_CROP_FENCE);
    }
    std::printf("# clipping: three planes and cropping (%s) on every mapper\n",
      clipNothing ? "outside the volume, every region kept" : "fence");
  }

  if (shadeOnly)
  {
    // Surfaces inside the medium: as1 and as4 become the extended model with ShadeOn at the
    // default blending, asx1 and asx4 the unshaded program (blending 2).
    b.Property->ShadeOn();
    for (vtkAmbientScatteringVolumeMapper* m : { as1.Get(), as4.Get() })
    {
      m->SetScatteringModelToExtended();
      m->SetVolumetricScatteringBlending(0.0f);
    }
    asx1->SetVolumetricScatteringBlending(2.0f);
    asx4->SetVolumetricScatteringBlending(2.0f);
    b.SetLights(1);
    const std::vector<Bench::Timing> shadeOne = b.MeasureEach({ asx1, as1 });
    b.SetLights(4);
    const std::vector<Bench::Timing> shadeFour = b.MeasureEach({ asx4, as4 });
    std::printf("bench %s %.4f s\n", name("frame_asx1_unshaded").c_str(), shadeOne[0].Median);
    std::printf("bench %s %.4f s\n", name("frame_asx1_shaded").c_str(), shadeOne[1].Median);
    std::printf("bench %s %.4f s\n", name("frame_asx4_unshaded").c_str(), shadeFour[0].Median);
    std::printf("bench %s %.4f s\n", name("frame_asx4_shaded").c_str(), shadeFour[1].Median);
    std::printf("ratio %s %.3f\n",
      name("shade_over_unshaded").c_str(),
      Bench::RatioOf(shadeOne[0], shadeOne[1]));
    std::printf("ratio %s %.3f\n",
      name("shade4_over_unshaded4").c_str(),
      Bench::RatioOf(shadeFour[0], shadeFour[1]));
    return 0;
  }

  // The frames: with one light VTK's EA, ours, AO and ambient scattering in alternation, then
  // with four lights our EA (which does not use them) and both ambient-scattering models in
  // alternation. Each ratio is the median of the per-position ratios of two mappers' frames, so
  // that it does not follow the machine's drifts.
  std::vector<Bench::Timing> one;
  if (!modelsOnly)
  {
    one = b.MeasureEach({ vtkEA, ea, ao, as1, asx1 });
    std::printf("bench %s %.4f s\n", name("frame_vtk_ea").c_str(), one[0].Median);
    std::printf("bench %s %.4f s\n", name("frame_ea").c_str(), one[1].Median);
    std::printf("bench %s %.4f s\n", name("frame_ao").c_str(), one[2].Median);
    std::printf("bench %s %.4f s\n", name("first_frame_ao").c_str(), one[2].First);
    std::printf("bench %s %.4f s\n", name("frame_as1").c_str(), one[3].Median);
    std::printf("bench %s %.4f s\n", name("first_frame_as1").c_str(), one[3].First);
    std::printf("bench %s %.4f s\n", name("frame_asx1").c_str(), one[4].Median);
    std::printf("bench %s %.4f s\n", name("first_frame_asx1").c_str(), one[4].First);
  }
  b.SetLights(4);
  std::vector<Bench::Timing> four =
    modelsOnly ? b.MeasureEach({ as4, asx4 }) : b.MeasureEach({ ea, as4, asx4 });
  if (modelsOnly)
  {
    four.insert(four.begin(), Bench::Timing());
  }
  const double modelsRatio = Bench::RatioOf(four[1], four[2]);
  std::printf("bench %s %.4f s\n", name("frame_as4").c_str(), four[1].Median);
  std::printf("bench %s %.4f s\n", name("first_frame_as4").c_str(), four[1].First);
  std::printf("bench %s %.4f s\n", name("frame_asx4").c_str(), four[2].Median);
  std::printf("bench %s %.4f s\n", name("first_frame_asx4").c_str(), four[2].First);
  // The frames' ratios: ours against VTK's EA, each ambient-scattering mapper against our EA
  // (the paper's model as and as4, the extended one asx and asx4).
  auto frameRatios = [&]()
  {
    std::printf("ratio %s %.3f\n", name("ea_over_vtk_ea").c_str(), Bench::RatioOf(one[0], one[1]));
    std::printf("ratio %s %.3f\n", name("as_over_ea").c_str(), Bench::RatioOf(one[1], one[3]));
    std::printf("ratio %s %.3f\n", name("asx_over_ea").c_str(), Bench::RatioOf(one[1], one[4]));
    std::printf("ratio %s %.3f\n", name("as4_over_ea").c_str(), Bench::RatioOf(four[0], four[1]));
    std::printf("ratio %s %.3f\n", name("asx4_over_ea").c_str(), Bench::RatioOf(four[0], four[2]));
    std::printf("ratio %s %.3f\n", name("ao_over_ea").c_str(), Bench::RatioOf(one[1], one[2]));
  };
  if (framesOnly)
  {
    if (!modelsOnly)
    {
      frameRatios();
    }
    std::printf("ratio %s %.3f\n", name("asx4_over_as4").c_str(), modelsRatio);
    return 0;
  }

  // Rebuilds with 4 lights, the two models in alternation: after each change (five
  // transfer-function changes, then five moves of one light) each model renders the frame that
  // rebuilds and then one that does not; the rebuild is their difference, the median over the
  // changes. Returns false if the rebuilds were not those.
  double tfRebuild = 0.0, lightRebuild = 0.0, tfRebuildX = 0.0, lightRebuildX = 0.0;
  {
    vtkAmbientScatteringVolumeMapper* mappers[2] = { as4, asx4 };
    const auto volumes = b.AddVolumes({ as4, asx4 });
    auto frame = [&](int shown) { return b.FrameOf(volumes, static_cast<std::size_t>(shown)); };
    frame(0);
    frame(1);
    const int changes = 5;
    std::vector<double> tf[2], light[2];
    int extinctionBefore[2], lightsBefore[2];
    for (int m = 0; m < 2; ++m)
    {
      extinctionBefore[m] = mappers[m]->GetNumberOfExtinctionRebuilds();
    }
    for (int c = 0; c < changes; ++c)
    {
      b.Opacity->AddPoint(0.75, c % 2 == 0 ? 0.45 : 0.40);
      for (int m = 0; m < 2; ++m)
      {
        const double rebuilt = frame(m);
        tf[m].push_back(rebuilt - frame(m));
      }
    }
    for (int m = 0; m < 2; ++m)
    {
      lightsBefore[m] = mappers[m]->GetNumberOfLightVolumeRebuilds();
    }
    for (int c = 0; c < changes; ++c)
    {
      b.Lights[1]->SetPosition(0.1, 0.05 * (c + 1), 0.0);
      for (int m = 0; m < 2; ++m)
      {
        const double rebuilt = frame(m);
        light[m].push_back(rebuilt - frame(m));
      }
    }
    b.RemoveVolumes(volumes);
    for (int m = 0; m < 2; ++m)
    {
      if (mappers[m]->GetNumberOfExtinctionRebuilds() - extinctionBefore[m] != changes ||
        mappers[m]->GetNumberOfLightVolumeRebuilds() - lightsBefore[m] != changes)
      {
        std::fprintf(stderr, "avs-bench-mappers: the rebuilds were not the ones measured\n");
        return 1;
      }
    }
    tfRebuild = Median(tf[0]);
    lightRebuild = Median(light[0]);
    tfRebuildX = Median(tf[1]);
    lightRebuildX = Median(light[1]);
  }
  std::printf("bench %s %.4f s\n", name("rebuild_transfer_function_as4").c_str(), tfRebuild);
  std::printf("bench %s %.4f s\n", name("rebuild_light_move_as4").c_str(), lightRebuild);
  std::printf("bench %s %.4f s\n", name("rebuild_transfer_function_asx4").c_str(), tfRebuildX);
  std::printf("bench %s %.4f s\n", name("rebuild_light_move_asx4").c_str(), lightRebuildX);

  if (modelsOnly)
  {
    std::printf("ratio %s %.3f\n", name("asx4_over_as4").c_str(), modelsRatio);
    std::printf(
      "ratio %s %.3f\n", name("tf_rebuild_asx4_over_as4").c_str(), tfRebuildX / tfRebuild);
    return 0;
  }
  frameRatios();
  std::printf(
    "ratio %s %.3f\n", name("tf_rebuild_over_ea_frame").c_str(), tfRebuild / four[0].Median);
  std::printf("ratio %s %.3f\n", name("asx4_over_as4").c_str(), modelsRatio);
  std::printf("ratio %s %.3f\n", name("tf_rebuild_asx4_over_as4").c_str(), tfRebuildX / tfRebuild);
  if (!RunInteraction(b, lightGrid, suffix))
  {
    std::fprintf(stderr, "avs-bench-mappers: light volumes were rebuilt while interacting\n");
    return 1;
  }
  return 0;
}
