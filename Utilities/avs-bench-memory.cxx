// avs-bench-memory: what the mappers take in memory, side by side with VTK's
// vtkGPUVolumeRayCastMapper. Lines:
//
//   memory <mapper> <type> gpu_bytes_per_voxel <B> (peak <B>) peak_above_baseline <MiB>
//     first_frame <s> rebuild_opacity <s> (cpu <s>) frame <s> frame_cpu <s>
//   PASS|FAIL <target>: <figures>
//
// Scene: the built-in nebula (MakeNebula, --voxels N per axis, default 256) as 8-bit and as
// 16-bit unsigned scalars, --size S pixels square (default 256), the transfer functions of
// avs-bench-mappers, jittering off. Mappers: VTK's (composite, unshaded), ours EA, AO, and
// ambient scattering with 1 and with 4 lights. Each configuration runs in a child process of
// its own (fork), so that the peaks do not mix: the child makes its window and renders an empty
// frame, resets its peak resident set size to the current one (writing 5 to
// /proc/self/clear_refs) and reads VmRSS (the baseline: the process with its GL context and the
// input volume), then renders a first frame (uploads and precomputation) and --frames frames
// turning the camera 3 degrees each, then one frame after an opacity change (which rebuilds
// the scattering volumes; reported less the median frame); it reports VmHWM less the baseline (on
// llvmpipe the textures live in host memory, so this includes them), the median frame time, the
// process's CPU time per frame (llvmpipe renders on the process's threads, so this is the frame's
// work, steadier than its wall time on a loaded machine) and, for ours, the bytes of its GPU
// textures per voxel (vtkAVSVolumeMapper::GetGPUMemoryBytes, our own accounting of every 3D
// texture), held after the frames and at most during them (peak: GetGPUMemoryPeakBytes, with the
// precomputation's intermediate grids). VTK's bytes per voxel are not measured but estimated from
// the format its vtkVolumeTexture uploads a one-component volume in (the array's own type: R8 for
// 8-bit, R16 for 16-bit scalars: 1 and 2 bytes per voxel; its 2D tables and noise texture are not
// counted, as ours are not). Then ambient scattering with 4 lights on the 8-bit volume once more
// under AVS_GPU_MEMORY_LIMIT_MB=1024 (the 1 GB budget). as1 and as4 are the paper's model,
// asx4 the extended one (the default) with 4 lights. --mappers vtk_ea,ea,ao,as1,as4,asx4 (any of
// them) runs only those, without the targets.
//
// Targets: ours EA <= 1.1x VTK's bytes per voxel and peak above baseline; ambient
// scattering with 4 lights <= 2.5x VTK's (EA) in both; the 8-bit volume renders with ambient
// scattering within 1 GB (meant at --voxels 512).
#include "BenchScene.h"
#include "ProceduralVolume.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace
{
/// A field of /proc/self/status in KiB (VmRSS, VmHWM), 0 when absent.
double StatusKiB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(status, line))
  {
    if (line.compare(0, key.size(), key) == 0)
    {
      return std::atof(line.c_str() + key.size());
    }
  }
  return 0.0;
}

/// User and system CPU time of this process so far (all its threads).
double CPUSeconds()
{
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// Resets VmHWM to the current VmRSS (Linux 4.0 and later); false where refused.
bool ResetPeak()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

struct Result
{
  double BytesPerVoxel = 0.0;     // GPU textures (ours: counted; VTK's: estimated)
  double PeakBytesPerVoxel = 0.0; // ours: the most held at once (the precomputation's grids)
  double First = 0.0;             // the first frame (uploads and precomputation)
  double Rebuild = 0.0;           // the frame after an opacity change, less the median frame
  double PeakMiB = 0.0;           // VmHWM above the baseline
  double Frame = 0.0;             // median frame time
  double RebuildCPU = 0.0;        // the same in CPU time
  double FrameCPU = 0.0;          // CPU time of the process (llvmpipe's threads too) per frame
  int Errors = 0;
};

class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Errors;
    std::fprintf(stderr, "error: %s\n", data ? static_cast<const char*>(data) : "");
  }
  int Errors = 0;
};

/// One configuration, in this (child) process.
Result RunOne(const std::string& mapperName, vtkImageData* volume, int size, int frames)
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(size, size);
  window->SetMultiSamples(0);
  window->OffScreenRenderingOn();
  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff(); // the lights below, no others
  window->AddRenderer(renderer);
  window->Render(); // the context, before the baseline

  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  const double top = volume->GetPointData()->GetScalars()->GetDataTypeMax();
  ConfigureBenchProperty(property, color, opacity, top);
  const std::vector<vtkSmartPointer<vtkLight>> lights = MakeBenchLights();
  for (int i = 0; i < (mapperName == "as4" || mapperName == "asx4" ? 4 : 1); ++i)
  {
    renderer->AddLight(lights[i]);
  }

  vtkSmartPointer<vtkVolumeMapper> mapper;
  vtkAVSVolumeMapper* ours = nullptr;
  const double step = 0.5 * volume->GetSpacing()[0];
  if (mapperName == "vtk_ea")
  {
    auto vtk = vtkSmartPointer<vtkGPUVolumeRayCastMapper>::New();
    vtk->SetSampleDistance(step);
    vtk->SetAutoAdjustSampleDistances(0);
    vtk->SetUseJittering(0);
    mapper = vtk;
  }
  else
  {
    vtkSmartPointer<vtkAVSVolumeMapper> m;
    if (mapperName == "ea")
      m = vtkSmartPointer<vtkEmissionAbsorptionVolumeMapper>::New();
    else if (mapperName == "ao")
      m = vtkSmartPointer<vtkAmbientOcclusionVolumeMapper>::New();
    else
    {
      // as1, as4: the paper's model, which the targets are set for; asx4 the extended one (the
      // default), which adds its fluence on the light grid and the diffusion grids.
      auto scattering = vtkSmartPointer<vtkAmbientScatteringVolumeMapper>::New();
      if (mapperName != "asx4")
      {
        scattering->SetScatteringModelToPaper();
      }
      m = scattering;
    }
    m->SetSampleDistance(step);
    m->AutoAdjustSampleDistancesOff();
    m->UseJitteringOff();
    ours = m;
    mapper = m;
  }
  vtkNew<ErrorCounter> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->SetInputData(volume);
  vtkNew<vtkVolume> prop;
  prop->SetMapper(mapper);
  prop->SetProperty(property);

  const bool reset = ResetPeak();
  const double baseline = StatusKiB("VmRSS");
  renderer->AddVolume(prop);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.5, 0.7, 4.2);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
  const auto first = std::chrono::steady_clock::now();
  window->Render(); // uploads and precomputation
  window->WaitForCompletion();
  const double firstSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - first).count();
  std::vector<double> times;
  const double cpu0 = CPUSeconds();
  for (int f = 0; f < frames; ++f)
  {
    camera->Azimuth(3.0);
    renderer->ResetCameraClippingRange();
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    times.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const double cpu1 = CPUSeconds();
  // An opacity change: ours rebuild the extinction-dependent volumes (the scattering ones).
  opacity->AddPoint(0.75 * top, 0.3);
  const auto change = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  const double changed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - change).count();
  Result r;
  r.First = firstSeconds;
  r.FrameCPU = frames > 0 ? (cpu1 - cpu0) / frames : 0.0;
  r.RebuildCPU = CPUSeconds() - cpu1 - r.FrameCPU;
  r.PeakMiB = reset ? (StatusKiB("VmHWM") - baseline) / 1024.0 : -1.0;
  std::sort(times.begin(), times.end());
  r.Frame = times.empty() ? 0.0 : times[times.size() / 2];
  r.Rebuild = changed - r.Frame;
  const double voxels = static_cast<double>(volume->GetNumberOfPoints());
  if (ours)
  {
    r.BytesPerVoxel = ours->GetGPUMemoryBytes() / voxels;
    r.PeakBytesPerVoxel = ours->GetGPUMemoryPeakBytes() / voxels;
  }
  else
  {
    // Estimated: vtkVolumeTexture uploads the array's own type (R8, R16).
    r.BytesPerVoxel = r.PeakBytesPerVoxel = volume->GetPointData()->GetScalars()->GetDataTypeSize();
  }
  r.Errors = errors->Errors;
  renderer->RemoveVolume(prop);
  return r;
}

/// RunOne in a child process, its result sent back through a pipe.
bool RunChild(const std::string& mapperName, vtkImageData* volume, int size, int frames, Result& r)
{
  int fds[2];
  if (pipe(fds) != 0)
  {
    return false;
  }
  std::fflush(stdout);
  const pid_t pid = fork();
  if (pid < 0)
  {
    return false;
  }
  if (pid == 0)
  {
    close(fds[0]);
    const Result out = RunOne(mapperName, volume, size, frames);
    const ssize_t written = write(fds[1], &out, sizeof(out));
    close(fds[1]);
    _exit(written == static_cast<ssize_t>(sizeof(out)) ? 0 : 1);
  }
  close(fds[1]);
  const ssize_t got = read(fds[0], &r, sizeof(r));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return got == static_cast<ssize_t>(sizeof(r)) && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

vtkSmartPointer<vtkImageData> Quantized(const avs::Grid& nebula, int bits)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  const auto& g = nebula.Geometry;
  image->SetDimensions(g.Dimensions[0], g.Dimensions[1], g.Dimensions[2]);
  image->SetSpacing(g.Spacing.x, g.Spacing.y, g.Spacing.z);
  image->SetOrigin(g.Origin.x, g.Origin.y, g.Origin.z);
  const vtkIdType n = static_cast<vtkIdType>(nebula.Values.size());
  const double top = bits == 8 ? 255.0 : 65535.0;
  vtkSmartPointer<vtkDataArray> a;
  if (bits == 8)
  {
    auto u = vtkSmartPointer<vtkUnsignedCharArray>::New();
    u->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      u->SetValue(i, static_cast<unsigned char>(std::lround(top * nebula.Values[i])));
    a = u;
  }
  else
  {
    auto u = vtkSmartPointer<vtkUnsignedShortArray>::New();
    u->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      u->SetValue(i, static_cast<unsigned short>(std::lround(top * nebula.Values[i])));
    a = u;
  }
  a->SetName("density");
  image->GetPointData()->SetScalars(a);
  return image;
}

void Check(bool pass, const std::string& what, double value, double limit)
{
  std::printf("%s %s: %.3f (limit %.3f)\n", pass ? "PASS" : "FAIL", what.c_str(), value, limit);
}
} // namespace

int main(int argc, char* argv[])
{
  int voxels = 256, size = 256, frames = 3;
  std::string only; // --mappers a,b: only these (and no targets)
  for (int i = 1; i + 1 < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--mappers")
    {
      only = "," + std::string(argv[++i]) + ",";
    }
    else if (arg == "--voxels" || arg == "--size" || arg == "--frames")
    {
      const int v = std::max(2, std::atoi(argv[++i]));
      (arg == "--voxels" ? voxels : (arg == "--size" ? size : frames)) = v;
    }
  }
  std::printf("# memory: nebula %d^3, %d x %d pixels, %d frames after the first; peaks in "
              "MiB above a baseline (a child process per line: its window, its input volume); "
              "GPU bytes per voxel: ours counted, VTK's estimated from its upload format\n",
    voxels,
    size,
    size,
    frames);
  std::vector<vtkSmartPointer<vtkImageData>> volumes;
  {
    const avs::Grid nebula = avs::MakeNebula(voxels); // freed before the children start
    volumes.push_back(Quantized(nebula, 8));
    volumes.push_back(Quantized(nebula, 16));
  }
  const char* typeNames[2] = { "uint8", "uint16" };
  const char* mappers[6] = { "vtk_ea", "ea", "ao", "as1", "as4", "asx4" };
  std::map<std::string, Result> results;
  bool ok = true;
  for (int t = 0; t < 2; ++t)
  {
    for (const char* m : mappers)
    {
      if (!only.empty() && only.find("," + std::string(m) + ",") == std::string::npos)
      {
        continue;
      }
      Result r;
      if (!RunChild(m, volumes[t], size, frames, r))
      {
        std::printf("memory %s %s: the child failed\n", m, typeNames[t]);
        ok = false;
        continue;
      }
      std::printf(
        "memory %s %s gpu_bytes_per_voxel %.3f (peak %.3f) peak_above_baseline %.1f MiB "
        "first_frame %.3f s rebuild_opacity %.3f s (cpu %.3f s) frame %.4f s frame_cpu %.4f s%s\n",
        m,
        typeNames[t],
        r.BytesPerVoxel,
        r.PeakBytesPerVoxel,
        r.PeakMiB,
        r.First,
        r.Rebuild,
        r.RebuildCPU,
        r.Frame,
        r.FrameCPU,
        r.Errors ? " (errors)" : "");
      std::fflush(stdout);
      ok = ok && r.Errors == 0;
      results[std::string(m) + "_" + typeNames[t]] = r;
    }
  }
  if (!only.empty())
  {
    return ok ? 0 : 1;
  }
  for (int t = 0; t < 2; ++t)
  {
    const std::string k = std::string("_") + typeNames[t];
    const Result& vtk = results["vtk_ea" + k];
    const Result& ea = results["ea" + k];
    if (vtk.BytesPerVoxel <= 0.0 || vtk.PeakMiB <= 0.0)
    {
      continue;
    }
    Check(ea.BytesPerVoxel <= 1.1 * vtk.BytesPerVoxel,
      std::string("ea gpu bytes/voxel <= 1.1x vtk's, ") + typeNames[t],
      ea.BytesPerVoxel / vtk.BytesPerVoxel,
      1.1);
    Check(ea.PeakMiB <= 1.1 * vtk.PeakMiB,
      std::string("ea peak above baseline <= 1.1x vtk's, ") + typeNames[t],
      ea.PeakMiB / vtk.PeakMiB,
      1.1);
    for (const std::string name : { "as4", "asx4" })
    {
      const Result& as = results[name + k];
      Check(as.BytesPerVoxel <= 2.5 * vtk.BytesPerVoxel,
        name + " gpu bytes/voxel held <= 2.5x vtk's ea, " + typeNames[t],
        as.BytesPerVoxel / vtk.BytesPerVoxel,
        2.5);
      // What it allocates at once during a rebuild (the averaged-extinction pass's scratch
      // grids beside the rest): the stricter reading of "allocates".
      Check(as.PeakBytesPerVoxel <= 2.5 * vtk.BytesPerVoxel,
        name + " gpu bytes/voxel at the rebuild's peak <= 2.5x vtk's ea, " + typeNames[t],
        as.PeakBytesPerVoxel / vtk.BytesPerVoxel,
        2.5);
      Check(as.PeakMiB <= 2.5 * vtk.PeakMiB,
        name + " peak above baseline <= 2.5x vtk's ea, " + typeNames[t],
        as.PeakMiB / vtk.PeakMiB,
        2.5);
    }
  }
  // The 1 GB budget: ambient scattering, 4 lights, the 8-bit volume.
  setenv("AVS_GPU_MEMORY_LIMIT_MB", "1024", 1);
  for (const std::string name : { "as4", "asx4" })
  {
    Result budget;
    const bool ran = RunChild(name, volumes[0], size, 1, budget);
    const double mib =
      budget.PeakBytesPerVoxel * volumes[0]->GetNumberOfPoints() / (1024.0 * 1024.0);
    Check(ran && budget.Errors == 0 && mib <= 1024.0,
      name + " uint8 " + std::to_string(voxels) +
        "^3 renders within AVS_GPU_MEMORY_LIMIT_MB=1024, peak MiB",
      mib,
      1024.0);
  }
  return ok ? 0 : 1;
}
