// avs-bench-refinement: how fast the path-traced refinement of vtkAmbientScatteringVolumeMapper
// (SetPathTracedRefinement) takes the ambient-scattering (AS) picture towards the truth on the
// accuracy study's scenes (AccuracyStudy.h), against the CPU path tracer and VTK's shaded frame.
// Lines `bench <name> <value> [s | spp]`, `ratio <name> <value>`, `rmse <scene> ...` (a table).
//
// Per scene: the truth (the study's: the mean of two CPU path-traced pictures of --truth-spp
// samples per pixel); the study's AS mapper (extended model, exposure 1, clamp); then its still
// frames with the refinement on, one GPU path-traced sample per pixel each, every frame read back
// (vtkAVSVolumeMapper::GetRefinementBuffers) and measured as the user sees it (avs::RefinedPicture,
// then the display transform), up to --max-spp. The clock runs over Render() and
// WaitForCompletion() alone (not the readback nor the RMSE), from the first still frame of a rest
// (after a camera step and back, as after an interaction; it also captures the AS picture).
// Reported: the samples and seconds at which the refined picture's RMSE first reaches 1/2 and 1/4
// of the AS picture's (-1 when not within --max-spp), the same for the CPU path tracer
// (avs::RenderPathTraced, another seed, at 1, 2, 4, ... samples per pixel, each run timed), and
// the frame times of VTK's vtkGPUVolumeRayCastMapper with ShadeOn, of the AS frame and of one
// refinement frame. The RMSE is the study's (AccuracyRmse): over R, G and B on the study's linear
// exposure, clamped to [0, 1] as the framebuffer clamps (as the truth is kept; the background is
// black, so the premultiplied radiance is what the pixel shows), with the truth's own noise taken
// out: sqrt(RMSE^2 - noise^2), the noise measured from the truth's two seeds (a picture's error
// and the truth's are independent, so their squares add; without this, a picture as good as the
// truth would still measure the truth's noise, and the targets of a good AS picture could not be
// reached by any picture).
#include "AccuracyStudy.h"

#include "DisplayTransform.h"
#include "PathTracer.h"
#include "Refinement.h"

#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

/// An RMSE against the truth with the truth's own noise (RMSE) taken out.
double WithoutTruthNoise(double rmse, double noise)
{
  return std::sqrt(std::max(rmse * rmse - noise * noise, 0.0));
}

/// The CPU path tracer's seed: the truth's are 17 and 18.
constexpr std::uint64_t CpuSeed = 101;
/// The refined pictures the --output picture shows.
constexpr int PictureSamples[2] = { 16, 256 };

struct BenchSettings
{
  AccuracySettings Study;
  int MaximumSamples = 1024;
  int Frames = 5; ///< timed frames after two warm-up ones
  std::string OutputPicture;
};

/// When an RMSE target was first reached (-1: not within the samples allowed).
struct Target
{
  double Rmse = 0.0;
  int Samples = -1;
  double Seconds = -1.0;
  int PowerSamples = -1; ///< the first power of two of samples at which it was measured reached
  double PowerSeconds = -1.0;
};

/// The RMSEs after one more sample per pixel (Cpu: -1 where the CPU did not run that many).
struct Row
{
  double Seconds = 0.0; ///< the refinement's time so far
  double Refined = 0.0;
  double Mean = 0.0;
  double Cpu = -1.0;
  double CpuSeconds = -1.0;
};

struct SceneResult
{
  double AsRmse = 0.0;
  double Noise = 0.0; ///< the truth's own RMSE
  double VtkShadedFrame = 0.0, AsFrame = 0.0;
  double Frame = 0.0;          ///< a refinement frame (one sample per pixel)
  double FirstFrame = 0.0;     ///< the first of a rest (the AS picture and one sample)
  double ColdFirstFrame = 0.0; ///< the first of the mapper's first rest (shader compilation)
  Target Gpu[2], Cpu[2];       ///< 1/2 and 1/4 of the AS picture's RMSE
  int Samples = 0;             ///< samples per pixel the refinement reached
  double WorstRefinedOverAs = 0.0;
  int WorstAt = 0;
  std::vector<Row> Rows; ///< by samples per pixel, from 1
};

bool IsPowerOfTwo(int n)
{
  return n > 0 && (n & (n - 1)) == 0;
}

double TimedRender(vtkRenderWindow* window)
{
  const auto start = Clock::now();
  window->Render();
  window->WaitForCompletion();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The mean time of `frames` still frames after two warm-up ones.
double MeanFrame(vtkRenderWindow* window, int frames)
{
  TimedRender(window);
  TimedRender(window);
  double sum = 0.0;
  for (int i = 0; i < frames; ++i)
  {
    sum += TimedRender(window);
  }
  return sum / frames;
}

/// What the display shows of premultiplied linear RGBA: the study's display transform (exposure
/// 1, clamp), clamped to [0, 1] by the framebuffer; RGB, row 0 at the bottom.
std::vector<double> Displayed(const std::vector<float>& rgba)
{
  const avs::DisplayTransform display; // exposure 1, clamp: the study's linear exposure
  std::vector<double> rgb(3 * (rgba.size() / 4));
  for (std::size_t i = 0; 4 * i < rgba.size(); ++i)
  {
    const avs::Vec3 v = display.Apply({ rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2] });
    rgb[3 * i] = std::clamp(v.x, 0.0, 1.0);
    rgb[3 * i + 1] = std::clamp(v.y, 0.0, 1.0);
    rgb[3 * i + 2] = std::clamp(v.z, 0.0, 1.0);
  }
  return rgb;
}

std::vector<float> Values(vtkFloatArray* array)
{
  const float* p = array->GetPointer(0);
  return std::vector<float>(p, p + array->GetNumberOfValues());
}

/// Records the first time `rmse` reaches each target.
void Reach(Target (&targets)[2], double rmse, int samples, double seconds)
{
  for (Target& t : targets)
  {
    if (rmse <= t.Rmse && t.Samples < 0)
    {
      t.Samples = samples;
      t.Seconds = seconds;
    }
    if (rmse <= t.Rmse && t.PowerSamples < 0 && IsPowerOfTwo(samples))
    {
      t.PowerSamples = samples;
      t.PowerSeconds = seconds;
    }
  }
}

/// The 1-minute load average (other work on the cores skews every time here), "?" if unknown.
std::string LoadAverage()
{
  std::string load = "?";
  std::ifstream("/proc/loadavg") >> load;
  return load;
}

/// The OpenGL renderer's name ("OpenGL renderer string" of vtkRenderWindow::ReportCapabilities).
std::string OpenGLRenderer()
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(8, 8);
  window->OffScreenRenderingOn();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  const std::string report = window->ReportCapabilities();
  const std::string label = "OpenGL renderer string:";
  const std::size_t at = report.find(label);
  if (at == std::string::npos)
  {
    return "unknown";
  }
  const std::size_t begin = report.find_first_not_of(' ', at + label.size());
  return report.substr(begin, report.find('\n', begin) - begin);
}

/// Whether the installed ParaView has a path tracer (OSPRay or ANARI, through VTK's
/// RenderingRayTracing or RenderingAnari): a look for their libraries in the library folders
/// and ParaView's own.
std::string ParaViewPathTracer()
try
{
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> folders = { "/usr/lib", "/usr/local/lib" };
  for (const auto& entry : fs::directory_iterator("/usr/lib", ec))
  {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory(ec) && name.size() > 10 &&
      name.compare(name.size() - 10, 10, "-linux-gnu") == 0)
    {
      folders.push_back(entry.path());
    }
  }
  const auto isPathTracer = [](const std::string& name)
  {
    return name.rfind("libvtkRenderingRayTracing", 0) == 0 || name.rfind("libospray", 0) == 0 ||
      name.rfind("libanari", 0) == 0 || name.find("RenderingAnari") != std::string::npos;
  };
  std::vector<fs::path> paraview, found;
  std::string version;
  for (const fs::path& folder : folders)
  {
    for (const auto& entry : fs::directory_iterator(folder, ec))
    {
      const std::string name = entry.path().filename().string();
      if (name.rfind("paraview-", 0) == 0 && entry.is_directory(ec))
      {
        paraview.push_back(entry.path());
        version = name.substr(9);
      }
      else if (isPathTracer(name))
      {
        found.push_back(entry.path());
      }
    }
  }
  for (const fs::path& folder : paraview) // its plugins, at any depth
  {
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    {
      if (isPathTracer(it->path().filename().string()))
      {
        found.push_back(it->path());
      }
    }
    ec.clear();
  }
  std::string line;
  if (!found.empty())
  {
    line = "found";
    for (const fs::path& p : found)
    {
      line += " " + p.string();
    }
    return line;
  }
  if (paraview.empty())
  {
    return "none (no ParaView installed, and no OSPRay or ANARI library)";
  }
  const bool debian = fs::exists("/var/lib/dpkg/info/paraview.list", ec);
  line = std::string("none (") + (debian ? "Debian's " : "") + "ParaView " + version +
    " is built without OSPRay/ANARI: no libvtkRenderingRayTracing, libospray or libanari in";
  for (const fs::path& p : folders)
  {
    line += " " + p.string();
  }
  for (const fs::path& p : paraview)
  {
    line += " " + p.string();
  }
  return line + ")";
}
catch (const std::exception& e)
{
  return std::string("unknown (") + e.what() + " while looking)";
}

/// One line `<kind> refine_<key>_<scene> <value>[ <unit>]`.
void Print(const char* kind,
  const std::string& key,
  const std::string& scene,
  double value,
  int digits,
  const char* unit = "")
{
  std::printf("%s refine_%s_%s %.*f%s\n", kind, key.c_str(), scene.c_str(), digits, value, unit);
}

/// Measures one scene; appends its row of pictures to `rows` when given. False when the mapper
/// could not refine.
bool MeasureScene(const BenchSettings& settings,
  const std::string& name,
  SceneResult& r,
  vtkImageAppend* rows)
{
  const AccuracySettings& study = settings.Study;
  const int size = study.ImageSize;
  vtkNew<vtkRenderWindow> window;
  window->SetSize(size, size);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0, 0, 0);
  window->AddRenderer(renderer);
  const AccuracyScene scene = SetUpAccuracyScene(study, name, renderer);

  // 1. The truth.
  auto start = Clock::now();
  const std::vector<double> truth = AccuracyTruth(study, scene, &r.Noise);
  std::printf("# %s: truth (2 x %d samples per pixel) in %.1f s, its own noise (RMSE) %.4f\n",
    name.c_str(),
    study.SamplesPerPixel,
    std::chrono::duration<double>(Clock::now() - start).count(),
    r.Noise);
  std::fflush(stdout);

  // 4. VTK's shaded frame: the same property shaded, the same sample distance, no jittering.
  {
    vtkNew<vtkVolumeProperty> shaded;
    shaded->DeepCopy(scene.Property);
    shaded->ShadeOn();
    vtkNew<vtkGPUVolumeRayCastMapper> mapper;
    mapper->SetInputData(scene.Data);
    mapper->SetAutoAdjustSampleDistances(0);
    mapper->SetSampleDistance(scene.Parameters.SampleDistance);
    mapper->UseJitteringOff();
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(shaded);
    renderer->AddVolume(volume);
    r.VtkShadedFrame = MeanFrame(window, settings.Frames);
    renderer->RemoveVolume(volume);
  }

  // 2. Our ambient-scattering frame (refinement off), then the refinement on the same mapper.
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  ConfigureAccuracyMapper(as, scene, study);
  as->SetScatteringModelToExtended();
  as->SetInputData(scene.Data);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(as);
  volume->SetProperty(scene.Property);
  renderer->AddVolume(volume);
  r.AsFrame = MeanFrame(window, settings.Frames);
  const double grabbedRmse = WithoutTruthNoise(AccuracyRmse(AccuracyGrab(window), truth), r.Noise);

  // A first rest (its first frame compiles the path tracer's shaders), a step of the camera and
  // back: the rest measured starts from a restart, as after an interaction.
  as->PathTracedRefinementOn();
  as->SetMaximumSamplesPerPixel(settings.MaximumSamples);
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkNew<vtkCamera> saved;
  saved->DeepCopy(camera);
  r.ColdFirstFrame = TimedRender(window);
  TimedRender(window);
  camera->Azimuth(1.0);
  TimedRender(window);
  camera->DeepCopy(saved);

  vtkNew<vtkFloatArray> ambient, mean, meanOfSquares;
  avs::RefinementBuffers buffers;
  buffers.Width = buffers.Height = size;
  std::vector<double> asPicture, refinedPictures[2];
  double seconds = 0.0;
  while (r.Samples < settings.MaximumSamples)
  {
    const double frame = TimedRender(window);
    seconds += frame;
    const int samples = as->GetSamplesPerPixel();
    if (samples != r.Samples + 1 || !as->GetRefinementBuffers(ambient, mean, meanOfSquares))
    {
      std::fprintf(stderr,
        "avs-bench-refinement: %s: a still frame took the refinement from %d to %d samples per "
        "pixel, or its buffers could not be read\n",
        name.c_str(),
        r.Samples,
        samples);
      return false;
    }
    r.Samples = buffers.Samples = samples;
    buffers.Ambient = Values(ambient);
    buffers.Mean = Values(mean);
    buffers.MeanOfSquares = Values(meanOfSquares);
    if (samples == 1)
    {
      r.FirstFrame = frame;
      asPicture = Displayed(buffers.Ambient);
      r.AsRmse = WithoutTruthNoise(AccuracyRmse(asPicture, truth), r.Noise);
      r.Gpu[0].Rmse = r.Cpu[0].Rmse = r.AsRmse / 2.0;
      r.Gpu[1].Rmse = r.Cpu[1].Rmse = r.AsRmse / 4.0;
    }
    const std::vector<double> refined = Displayed(avs::RefinedPicture(buffers));
    Row row;
    row.Seconds = seconds;
    row.Refined = WithoutTruthNoise(AccuracyRmse(refined, truth), r.Noise);
    row.Mean = WithoutTruthNoise(AccuracyRmse(Displayed(buffers.Mean), truth), r.Noise);
    r.Rows.push_back(row);
    Reach(r.Gpu, row.Refined, samples, seconds);
    if (r.AsRmse > 0.0 && row.Refined / r.AsRmse > r.WorstRefinedOverAs)
    {
      r.WorstRefinedOverAs = row.Refined / r.AsRmse;
      r.WorstAt = samples;
    }
    for (int i = 0; i < 2; ++i)
    {
      if (samples == std::min(PictureSamples[i], settings.MaximumSamples))
      {
        refinedPictures[i] = refined;
      }
    }
  }
  r.Frame = r.Samples > 1 ? (seconds - r.FirstFrame) / (r.Samples - 1) : r.FirstFrame;
  renderer->RemoveVolume(volume);
  std::printf("# %s: the study's AS picture (8-bit framebuffer, refinement off) RMSE %.4f; the "
              "refinement's AS buffer %.4f\n",
    name.c_str(),
    grabbedRmse,
    r.AsRmse);

  // 3. The CPU path tracer, another seed, at 1, 2, 4, ... samples per pixel, each run timed.
  avs::PathTracerSettings pts;
  pts.Seed = CpuSeed;
  for (int samples = 1; samples <= settings.MaximumSamples && r.Cpu[1].Samples < 0; samples *= 2)
  {
    pts.SamplesPerPixel = samples;
    start = Clock::now();
    const avs::Image image =
      avs::RenderPathTraced(scene.Core, scene.Parameters, pts, scene.Camera, size, size);
    Row& row = r.Rows[samples - 1];
    row.CpuSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    row.Cpu = WithoutTruthNoise(AccuracyRmse(ClampedRgb(image), truth), r.Noise);
    Reach(r.Cpu, row.Cpu, samples, row.CpuSeconds);
  }

  if (rows)
  {
    vtkNew<vtkImageAppend> pictures;
    pictures->SetAppendAxis(0);
    const std::vector<const std::vector<double>*> columns = {
      &asPicture, &refinedPictures[0], &refinedPictures[1], &truth
    };
    for (const std::vector<double>* picture : columns)
    {
      pictures->AddInputData(AccuracyPicture(*picture, size));
    }
    pictures->Update();
    vtkNew<vtkImageData> copy;
    copy->DeepCopy(pictures->GetOutput());
    rows->AddInputData(copy);
  }
  return true;
}

void Report(const BenchSettings& settings, const std::string& name, const SceneResult& r)
{
  std::printf("# %s: RMSE against the truth by samples per pixel (spp): as, the ambient-"
              "scattering picture; refined, what is shown; mean, the GPU path tracer's running "
              "mean; cpu, avs::RenderPathTraced at that spp (powers of two); gpu_s, the "
              "refinement's time so far; cpu_s, the CPU run's\n",
    name.c_str());
  std::printf("#    scene           spp    gpu_s      as  refined    mean     cpu    cpu_s\n");
  for (int samples = 1; samples <= r.Samples; ++samples)
  {
    if (!IsPowerOfTwo(samples) && samples != r.Samples && samples != r.WorstAt &&
      samples != r.Gpu[0].Samples && samples != r.Gpu[1].Samples)
    {
      continue;
    }
    const Row& row = r.Rows[samples - 1];
    char cpu[2][32] = { "-", "-" };
    if (row.Cpu >= 0)
    {
      std::snprintf(cpu[0], sizeof(cpu[0]), "%.4f", row.Cpu);
      std::snprintf(cpu[1], sizeof(cpu[1]), "%.3f", row.CpuSeconds);
    }
    std::printf("rmse %-13s %5d %8.3f %7.4f %8.4f %7.4f %7s %8s\n",
      name.c_str(),
      samples,
      row.Seconds,
      r.AsRmse,
      row.Refined,
      row.Mean,
      cpu[0],
      cpu[1]);
  }
  std::printf("# %s: the refined picture's RMSE is at most %.4f times the AS picture's over the "
              "%d frames (at %d spp): %s\n",
    name.c_str(),
    r.WorstRefinedOverAs,
    r.Samples,
    r.WorstAt,
    r.WorstRefinedOverAs <= 1.0 ? "never worse" : "WORSE than the AS picture there");
  Print("bench", "as_rmse", name, r.AsRmse, 4);
  const char* which[2] = { "half", "quarter" };
  for (int i = 0; i < 2; ++i)
  {
    const Target& t = r.Gpu[i];
    Print("bench", std::string(which[i]) + "_spp", name, t.Samples, 0, " spp");
    Print("bench", std::string(which[i]) + "_seconds", name, t.Seconds, 4, " s");
    if (t.Samples < 0)
    {
      std::printf("# %s: NOT REACHED: the refined picture's RMSE did not get to %s of the AS "
                  "picture's (%.4f) within %d spp (at %d: %.4f)\n",
        name.c_str(),
        which[i],
        t.Rmse,
        settings.MaximumSamples,
        r.Samples,
        r.Rows.empty() ? -1.0 : r.Rows.back().Refined);
    }
    if (t.Rmse <= r.Noise)
    {
      std::printf("# %s: %s of the AS picture's RMSE (%.4f) is below the truth's own noise "
                  "(%.4f), which every RMSE has taken out: measured with little precision; raise "
                  "--truth-spp\n",
        name.c_str(),
        which[i],
        t.Rmse,
        r.Noise);
    }
  }
  for (int i = 0; i < 2; ++i)
  {
    const Target& c = r.Cpu[i];
    Print("bench", std::string("cpu_") + which[i] + "_spp", name, c.Samples, 0, " spp");
    Print("bench", std::string("cpu_") + which[i] + "_seconds", name, c.Seconds, 4, " s");
    if (c.Samples < 0)
    {
      std::printf("# %s: NOT REACHED: the CPU path tracer's RMSE did not get to %s of the AS "
                  "picture's within %d spp\n",
        name.c_str(),
        which[i],
        settings.MaximumSamples);
    }
  }
  Print("bench", "vtk_shaded_frame", name, r.VtkShadedFrame, 4, " s");
  Print("bench", "as_frame", name, r.AsFrame, 4, " s");
  Print("bench", "pt_frame", name, r.Frame, 4, " s");
  Print("bench", "first_frame", name, r.FirstFrame, 4, " s");
  Print("bench", "cold_first_frame", name, r.ColdFirstFrame, 4, " s");
  // The two path tracers alone, estimator against estimator: the same paths (the tests hold
  // them equal pixel by pixel), so equal samples mean equal error: the GPU's frames (one sample
  // per pixel each) to the largest power of two both reached, over the CPU's run of as many.
  int common = 0;
  for (int samples = 1; samples <= static_cast<int>(r.Rows.size()); samples *= 2)
  {
    if (r.Rows[static_cast<std::size_t>(samples) - 1].CpuSeconds > 0.0)
    {
      common = samples;
    }
  }
  if (common > 0)
  {
    const Row& row = r.Rows[static_cast<std::size_t>(common) - 1];
    std::printf("# %s: the GPU path tracer's mean at %d spp: RMSE %.4f in %.3f s; the CPU's: %.4f "
                "in %.3f s\n",
      name.c_str(),
      common,
      row.Mean,
      r.Frame * common,
      row.Cpu,
      row.CpuSeconds);
    Print("ratio", "gpu_pt_over_cpu_pt", name, r.Frame * common / row.CpuSeconds, 3);
  }
  for (int i = 0; i < 2; ++i)
  {
    // The refined picture (ambient scattering as a control variate) against the CPU path
    // tracer, at the first power of two of samples per pixel that reaches the target (the CPU
    // path tracer is measured at powers of two only).
    const Target& g = r.Gpu[i];
    const Target& c = r.Cpu[i];
    const bool both = g.PowerSamples > 0 && c.Samples > 0 && c.Seconds > 0.0;
    Print("ratio",
      std::string("gpu_over_cpu_") + which[i],
      name,
      both ? g.PowerSeconds / c.Seconds : -1.0,
      both ? 3 : 0);
    const bool reached = g.Samples > 0 && r.VtkShadedFrame > 0.0;
    Print("ratio",
      std::string(which[i]) + "_over_vtk_shaded",
      name,
      reached ? g.Seconds / r.VtkShadedFrame : -1.0,
      reached ? 1 : 0);
    if (!both || !reached)
    {
      std::printf("# %s: the %s ratios are -1 where a target was not reached (above)\n",
        name.c_str(),
        which[i]);
    }
  }
  std::fflush(stdout);
}

int Usage()
{
  std::printf(
    "Usage: avs-bench-refinement [--scenes A,B,...] [--size N] [--voxels N] [--truth-spp N]\n"
    "                            [--max-spp N] [--frames N] [--truth-cache DIR]\n"
    "                            [--output FILE.png]\n"
    "\n"
    "How fast the ambient-scattering mapper's path-traced refinement takes its picture to\n"
    "1/2 and 1/4 of the ambient-scattering picture's RMSE against the truth, on the accuracy\n"
    "study's scenes, against the CPU path tracer and against VTK's shaded frame.\n"
    "  --scenes       some of cloud_back, cloud_side, nebula_point, dense_medical (the\n"
    "                 default four) and plume_point, comma-separated\n"
    "  --size         the picture's width and height in pixels\n"
    "  --voxels       the volumes' voxels per axis\n"
    "  --truth-spp    samples per pixel of each of the truth's two path-traced pictures\n"
    "  --max-spp      the refinement's MaximumSamplesPerPixel, and the CPU path tracer's\n"
    "  --frames       timed still frames of VTK's mapper and of the AS frame (after 2 more)\n"
    "  --truth-cache  a folder that keeps the truth between runs (avs-accuracy's cache: the\n"
    "                 same files for the same --size, --voxels and --truth-spp as its --spp)\n"
    "  --output       a PNG, one row per scene (bottom to top): AS | refined at 16 spp |\n"
    "                 refined at 256 spp (at --max-spp when fewer) | truth, on the linear\n"
    "                 exposure\n"
    "Defaults: --size 96 --voxels 64 --truth-spp 1024 --max-spp 1024 --frames 5\n"
    "Exit code: 0 when every scene reaches half the AS picture's RMSE, 1 otherwise.\n");
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  BenchSettings settings;
  settings.Study.SamplesPerPixel = 1024;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h")
    {
      return Usage();
    }
    if (i + 1 >= argc)
    {
      std::fprintf(stderr, "avs-bench-refinement: %s needs a value\n", arg.c_str());
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--size")
      settings.Study.ImageSize = std::max(8, std::atoi(value.c_str()));
    else if (arg == "--voxels")
      settings.Study.Voxels = std::max(8, std::atoi(value.c_str()));
    else if (arg == "--truth-spp")
      settings.Study.SamplesPerPixel = std::max(1, std::atoi(value.c_str()));
    else if (arg == "--max-spp")
      settings.MaximumSamples = std::max(1, std::atoi(value.c_str()));
    else if (arg == "--frames")
      settings.Frames = std::max(1, std::atoi(value.c_str()));
    else if (arg == "--truth-cache")
      settings.Study.TruthCache = value;
    else if (arg == "--output")
      settings.OutputPicture = value;
    else if (arg == "--scenes")
    {
      settings.Study.Scenes.clear();
      std::stringstream list(value);
      for (std::string scene; std::getline(list, scene, ',');)
      {
        settings.Study.Scenes.push_back(scene);
      }
    }
    else
    {
      std::fprintf(stderr, "avs-bench-refinement: unknown option %s\n", arg.c_str());
      return 2;
    }
  }
  if (!CheckAccuracySettings(settings.Study, "avs-bench-refinement"))
  {
    return 2;
  }

  const std::string renderer = OpenGLRenderer();
  const bool software = renderer.find("llvmpipe") != std::string::npos ||
    renderer.find("softpipe") != std::string::npos || renderer.find("SWR") != std::string::npos;
  std::printf("# avs-bench-refinement: %d x %d pixels, %d^3 voxels, truth 2 x %d spp, refinement "
              "up to %d spp, %u CPU threads, load average %s\n",
    settings.Study.ImageSize,
    settings.Study.ImageSize,
    settings.Study.Voxels,
    settings.Study.SamplesPerPixel,
    settings.MaximumSamples,
    std::thread::hardware_concurrency(),
    LoadAverage().c_str());
  std::printf("# OpenGL renderer: %s%s\n",
    renderer.c_str(),
    software ? " -- a software rasterizer: the \"GPU\" refinement and VTK's \"GPU\" mapper run "
               "on the CPU too, on the same cores as the CPU path tracer"
             : "");
  std::printf("paraview_path_tracer: %s\n", ParaViewPathTracer().c_str());
  std::fflush(stdout);

  vtkNew<vtkImageAppend> rows;
  rows->SetAppendAxis(1);
  bool allHalf = true;
  for (const std::string& name : settings.Study.Scenes)
  {
    SceneResult result;
    if (!MeasureScene(
          settings, name, result, settings.OutputPicture.empty() ? nullptr : rows.Get()))
    {
      allHalf = false;
      continue;
    }
    Report(settings, name, result);
    allHalf = allHalf && result.Gpu[0].Samples > 0;
  }
  if (!settings.OutputPicture.empty() && rows->GetNumberOfInputConnections(0) > 0)
  {
    rows->Update();
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(rows->GetOutputPort());
    writer->SetFileName(settings.OutputPicture.c_str());
    writer->Write();
    std::printf("# picture: %s (per scene, bottom to top: AS | refined at %d spp | refined at %d "
                "spp | truth)\n",
      settings.OutputPicture.c_str(),
      std::min(PictureSamples[0], settings.MaximumSamples),
      std::min(PictureSamples[1], settings.MaximumSamples));
  }
  std::printf("# every scene reached half the AS picture's RMSE: %s\n", allHalf ? "yes" : "no");
  return allHalf ? 0 : 1;
}
