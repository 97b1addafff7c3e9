#include "vtkEmissionAbsorptionVolumeMapper.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkEmissionAbsorptionVolumeMapper);

void vtkEmissionAbsorptionVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
