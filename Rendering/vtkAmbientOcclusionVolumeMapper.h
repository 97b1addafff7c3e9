/**
 * @class   vtkAmbientOcclusionVolumeMapper
 * @brief   GPU volume mapper with local volumetric ambient occlusion (ALGORITHM.md section 7)
 *
 * Emission–absorption with the colour scaled by k_amb AO(x) + k_e, where AO(x) is the mean
 * transmittance from x over NumberOfDirections well-spread directions up to OcclusionRadius
 * (Hernell, Ljung and Ynnerman 2010), computed once per change of the data, the transfer
 * functions, the radius or the direction count and stored in a volume. Optionally adds the
 * renderer's lights unshadowed (DirectLightWeight). The comparison mapper of the family.
 */
#ifndef vtkAmbientOcclusionVolumeMapper_h
#define vtkAmbientOcclusionVolumeMapper_h

#include "vtkAVSVolumeMapper.h"

#include <memory> // for std::unique_ptr

class vtkAVSOcclusionVolume;

class VTKRENDERINGAMBIENTSCATTERING_EXPORT vtkAmbientOcclusionVolumeMapper
  : public vtkAVSVolumeMapper
{
public:
  static vtkAmbientOcclusionVolumeMapper* New();
  vtkTypeMacro(vtkAmbientOcclusionVolumeMapper, vtkAVSVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Occlusion radius R in data units (world units for an untransformed volume). Default 0:
   * automatic, 1/64 of the volume's diagonal, at least the smallest voxel spacing and at most half
   * the volume's smallest side.
   */
  vtkSetClampMacro(OcclusionRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(OcclusionRadius, double);
  ///@}

  ///@{
  /**
   * Directions K, 14 to 1024. Default 32.
   */
  vtkSetClampMacro(NumberOfDirections, int, 14, 1024);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /**
   * Largest dimension per axis of the occlusion volume (the data's size, capped, keeping the
   * aspect ratio). Default 128: the occlusion varies on the scale of R, and its cost is K times
   * R's steps per grid point (on a 256^3 volume a cap of 128 computes it 8 times faster).
   */
  vtkSetClampMacro(OcclusionVolumeMaximumDimension, int, 2, 4096);
  vtkGetMacro(OcclusionVolumeMaximumDimension, int);
  ///@}

  ///@{
  /**
   * Weight k_amb of the occlusion term. Default 1.
   */
  vtkSetClampMacro(AmbientWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(AmbientWeight, double);
  ///@}

  ///@{
  /**
   * Emission weight k_e (colour regardless of occlusion). Default 0.
   */
  vtkSetClampMacro(EmissionWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(EmissionWeight, double);
  ///@}

  ///@{
  /**
   * Weight of the renderer's lights added without shadows. Default 0.
   */
  vtkSetClampMacro(DirectLightWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DirectLightWeight, double);
  ///@}

  ///@{
  /**
   * Multiplies the irradiance of every light of the direct term for this volume only (>= 0;
   * VTK light units, see vtkAmbientScatteringVolumeMapper::SetLightScale). Default 1.
   */
  vtkSetClampMacro(LightScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LightScale, double);
  ///@}

  ///@{
  /**
   * Whether the last occlusion volume was computed on the GPU, and how often it was rebuilt.
   */
  vtkTypeBool GetOcclusionOnGPU() override;
  int GetNumberOfOcclusionRebuilds() override;
  ///@}

protected:
  vtkAmbientOcclusionVolumeMapper();
  ~vtkAmbientOcclusionVolumeMapper() override;
  int GetEffect() const override { return 1; }
  void FillParameters(avs::ScatteringParameters& parameters) override;
  bool PrepareLighting(const vtkAVSPrecomputeInputs& inputs) override;
  void InvalidateLighting() override;
  void GetPrecomputedGrids(std::array<int, 3>& lightGrid,
    std::array<int, 3>& occlusionGrid) const override;

  double OcclusionRadius = 0.0;
  int NumberOfDirections = 32;
  int OcclusionVolumeMaximumDimension = 128;
  double AmbientWeight = 1.0;
  double EmissionWeight = 0.0;
  double DirectLightWeight = 0.0;
  double LightScale = 1.0;

private:
  vtkAmbientOcclusionVolumeMapper(const vtkAmbientOcclusionVolumeMapper&) = delete;
  void operator=(const vtkAmbientOcclusionVolumeMapper&) = delete;

  std::unique_ptr<vtkAVSOcclusionVolume> Occlusion; ///< the occlusion volume's owner
};

#endif
