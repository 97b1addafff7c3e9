/**
 * @class   vtkEmissionAbsorptionVolumeMapper
 * @brief   GPU emission–absorption volume mapper (ALGORITHM.md section 2)
 *
 * VTK's standard volume rendering model: front to back, each sample adds
 * T (1 - exp(-sigma_t dt)) c and attenuates T by exp(-sigma_t dt), with sigma_t from the
 * scalar opacity and its unit distance (VTK's opacity correction). No lights. It renders what
 * vtkGPUVolumeRayCastMapper renders without shading, and is the baseline the ambient-scattering
 * mapper's cost is measured against. See vtkAVSVolumeMapper for what all three mappers share.
 */
#ifndef vtkEmissionAbsorptionVolumeMapper_h
#define vtkEmissionAbsorptionVolumeMapper_h

#include "vtkAVSVolumeMapper.h"

class VTKRENDERINGAMBIENTSCATTERING_EXPORT vtkEmissionAbsorptionVolumeMapper
  : public vtkAVSVolumeMapper
{
public:
  static vtkEmissionAbsorptionVolumeMapper* New();
  vtkTypeMacro(vtkEmissionAbsorptionVolumeMapper, vtkAVSVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkEmissionAbsorptionVolumeMapper() = default;
  ~vtkEmissionAbsorptionVolumeMapper() override = default;
  int GetEffect() const override { return 0; }
  void FillParameters(avs::ScatteringParameters&) override {}

private:
  vtkEmissionAbsorptionVolumeMapper(const vtkEmissionAbsorptionVolumeMapper&) = delete;
  void operator=(const vtkEmissionAbsorptionVolumeMapper&) = delete;
};

#endif
