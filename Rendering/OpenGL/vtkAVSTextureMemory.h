/**
 * @class   vtkAVSTextureMemory
 * @brief   a GPU memory budget for the ray caster's volume textures (private)
 *
 * The 3D textures of a volume (scalars or their bricks, the averaged extinction, the light and
 * occlusion volumes, the scratch grids, the mask and the validity) may together be limited to
 * AVS_GPU_MEMORY_LIMIT_MB mebibytes (environment variable; unset or 0: no limit) and to the
 * mapper's budget (vtkAVSVolumeMapper::SetMaximumGPUMemory, ScopedBudget), the smaller of the two.
 * A texture that would take them past the limit is refused with an error before anything is
 * allocated, as a GPU that runs out of memory refuses it (GL_OUT_OF_MEMORY, which the ray caster
 * reports the same way); the mapper then releases what it had allocated for that volume. The limit
 * is read at every allocation, so a program (a test on a software rasterizer, which has no GPU
 * memory of its own to run out of) may set it at any time.
 */
#ifndef vtkAVSTextureMemory_h
#define vtkAVSTextureMemory_h

#include <array>
#include <string>
#include <vector>

class vtkTextureObject;

class vtkAVSTextureMemory
{
public:
  /// The limit in bytes: the smaller of AVS_GPU_MEMORY_LIMIT_MB's and the mapper's budget
  /// (ScopedBudget) where each is set (0: none).
  static double LimitBytes();

  /// The GPU memory the current context reports, in bytes: GL_NVX_gpu_memory_info's dedicated
  /// video memory (its total available memory on a device with unified memory, which reports
  /// almost no dedicated memory), or GL_ATI_meminfo's free texture memory; 0 where it reports
  /// none of them, or less than 64 MiB.
  static double ReportedBytes();

  /// The budget of the mapper whose frame is being prepared and drawn
  /// (vtkAVSVolumeMapper::SetMaximumGPUMemory, or what the context reports), in bytes (0: none),
  /// for the lifetime of this object (the mapper's Render; rendering runs on one thread).
  class ScopedBudget
  {
  public:
    explicit ScopedBudget(double bytes);
    ~ScopedBudget();
    ScopedBudget(const ScopedBudget&) = delete;
    ScopedBudget& operator=(const ScopedBudget&) = delete;

  private:
    double Previous;
  };

  /// Bytes of a 3D texture of `components` channels in `internalFormat` (0: 32-bit floats).
  static double Bytes(const std::array<int, 3>& dimensions,
    int components,
    unsigned int internalFormat);
  /// Bytes a texture object holds (0 for none).
  static double Bytes(vtkTextureObject* texture);

  /// Whether a new texture fits beside `held` (the textures kept, `replaced` among them or not:
  /// it is about to be released). On refusal says why in `error`.
  static bool Admit(const std::vector<vtkTextureObject*>& held,
    const vtkTextureObject* replaced,
    const std::array<int, 3>& dimensions,
    int components,
    unsigned int internalFormat,
    std::string& error);
};

#endif
