/**
 * @class   vtkAVSOcclusionVolume
 * @brief   the ambient-occlusion volume of a vtkAmbientOcclusionVolumeMapper (private)
 *
 * Owns the occlusion volume's cycle: the key it was built for (data and opacity versions,
 * radius, directions, grid), the rebuild (on the GPU when the context can, else on the CPU and
 * uploaded) when the key changed, and the count of rebuilds. Invalidate() forgets what the GPU
 * holds (a released window, a context switch): the next Update rebuilds.
 */
#ifndef vtkAVSOcclusionVolume_h
#define vtkAVSOcclusionVolume_h

#include <array>
#include <string>

struct vtkAVSPrecomputeInputs;

class vtkAVSOcclusionVolume
{
public:
  /// Rebuilds the occlusion volume when what it was built from changed; false with the reason.
  bool Update(const vtkAVSPrecomputeInputs& inputs, std::string& error);
  void Invalidate();

  /// The occlusion grid's dimensions (0 before the first build).
  const std::array<int, 3>& GetDimensions() const { return this->Dimensions; }
  int GetNumberOfRebuilds() const { return this->Rebuilds; }
  /// Whether the last build ran on the GPU.
  bool GetOnGPU() const { return this->OnGPU; }

private:
  std::array<int, 3> Dimensions{ 0, 0, 0 };
  int Key[2] = { -1, -1 }; ///< data and opacity versions
  double Radius = -1.0;
  int Directions = -1;
  bool Uploaded = false;
  bool OnGPU = false;
  int Rebuilds = 0;
};

#endif
