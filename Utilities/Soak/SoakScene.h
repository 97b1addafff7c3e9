// The soak's scene: two render windows, each with one volume whose mapper, data, transfer
// function, lights, camera, parameters and size change at random (but validly) from frame to
// frame, with bad input (an empty image, an image without scalars, a missing scattering table) at
// fixed frames. Everything random comes from one seeded generator, so a round of frames can be
// replayed exactly: the soak compares the rounds.
#ifndef SoakScene_h
#define SoakScene_h

#include "vtkSmartPointer.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

class vtkAVSVolumeMapper;
class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;
class vtkVolume;
class vtkVolumeProperty;
class SoakErrorCounter;

/// What the mappers count, summed over a window's mappers (they are replaced during a run).
struct SoakCounters
{
  long DataUploads = 0;
  long ExtinctionRebuilds = 0;
  long LightVolumeRebuilds = 0;
  long OcclusionRebuilds = 0;
  long RenderedFrames = 0;
  long Errors = 0;

  bool operator==(const SoakCounters& o) const;
  SoakCounters& operator+=(const SoakCounters& o);
  std::string ToString() const;
};

class SoakScene
{
public:
  enum class Kind
  {
    EmissionAbsorption,
    AmbientOcclusion,
    AmbientScattering
  };
  enum class Bad
  {
    None,
    EmptyImage,
    NoScalars,
    MissingTable
  };

  struct Window
  {
    vtkSmartPointer<vtkRenderWindow> RenderWindow;
    vtkSmartPointer<vtkRenderer> Renderer;
    vtkSmartPointer<vtkVolume> Volume;
    vtkSmartPointer<vtkVolumeProperty> Property;
    vtkSmartPointer<vtkAVSVolumeMapper> Mapper;
    vtkSmartPointer<SoakErrorCounter> Errors;
    Kind MapperKind = Kind::AmbientScattering;
    int Data = 0;            ///< index of the valid volume it shows
    Bad Pending = Bad::None; ///< the bad input of this frame, restored on the next
    SoakCounters Before;     ///< the mapper's counters before the frame
    SoakCounters Total;      ///< this round's increments
  };

  SoakScene();
  ~SoakScene();

  /// Back to the first frame's scene (new mappers, the base volume, default camera, lights,
  /// transfer function and window size) with the generator at `seed`.
  void Reset(std::uint64_t seed);

  /// Random changes for frame `frame` of a round (none in the quiet frames before a
  /// checkpoint), then both windows rendered. Returns false, with why in `failure`, when a
  /// frame did not do what it should: bad input must give an error and no frame, every other
  /// frame a picture without errors, and quiet frames no rebuild.
  bool Step(int frame, std::string& failure);

  /// Frames just before a checkpoint change nothing, so that no counter may move.
  static bool IsQuiet(int frame) { return frame % 50 >= 47; }
  static bool IsCheckpoint(int frame) { return frame % 50 == 49; }

  std::vector<Window>& Windows() { return this->W; }

private:
  double Uniform(double lo, double hi);
  int Integer(int lo, int hi);
  bool Chance(double p);

  void NewMapper(Window& w, Kind kind);
  void RandomLights(Window& w);
  void MoveLight(Window& w);
  void RandomTransferFunction(Window& w);
  void RandomParameters(Window& w);
  void MoveCamera(Window& w, bool large);
  void SetData(Window& w, int index);
  void Change(Window& w, int frame, int which);
  SoakCounters Read(Window& w) const;

  std::vector<Window> W;
  std::vector<vtkSmartPointer<vtkImageData>> Volumes; ///< valid: base, larger, smaller, rotated
  vtkSmartPointer<vtkImageData> Empty, NoScalars;
  std::mt19937_64 Random;
};

#endif
