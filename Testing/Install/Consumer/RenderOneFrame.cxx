// One frame of a ball with vtkAmbientScatteringVolumeMapper, from an installed package. Argument:
// the installed prefix, under which the shipped scattering table must have been found. Built with
// ImagingCore among the VTK components, the ball is cut by a VTK source (vtkRTAnalyticSource's
// field above the middle of its range); with ParallelMPI the mapper gets a vtkMPIController (not
// initialised: one process).
#include "vtkAmbientScatteringTable.h"
#include "vtkAmbientScatteringVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#ifdef AVS_CONSUMER_IMAGING
#include "vtkRTAnalyticSource.h"
#endif
#ifdef AVS_CONSUMER_MPI
#include "vtkMPIController.h"
#endif

#include <cmath>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  const std::string prefix = argc > 1 ? argv[1] : "";
  const std::string table = vtkAmbientScatteringTable::GetDefaultFileName();
  std::cout << "scattering table: " << table << "\n";
  if (prefix.empty() || table.rfind(prefix, 0) != 0)
  {
    std::cerr << "the table is not found in the installed tree " << prefix << "\n";
    return 1;
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(32, 32, 32);
  vtkNew<vtkFloatArray> s;
  s->SetNumberOfTuples(32 * 32 * 32);
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i)
      {
        const double r =
          std::sqrt((i - 15.5) * (i - 15.5) + (j - 15.5) * (j - 15.5) + (k - 15.5) * (k - 15.5));
        s->SetValue((k * 32 + j) * 32 + i, r < 12 ? 1.0f : 0.0f);
      }
  image->GetPointData()->SetScalars(s);
#ifdef AVS_CONSUMER_IMAGING
  // The ball cut by a VTK source: the wavelet's field above the middle of its range.
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(0, 31, 0, 31, 0, 31);
  wavelet->Update();
  vtkDataArray* field = wavelet->GetOutput()->GetPointData()->GetScalars();
  double range[2];
  field->GetRange(range);
  const double middle = 0.5 * (range[0] + range[1]);
  for (vtkIdType i = 0; i < field->GetNumberOfTuples(); ++i)
  {
    s->SetValue(i, s->GetValue(i) * static_cast<float>(field->GetComponent(i, 0) > middle));
  }
#endif
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 0.8, 0.6);
  color->AddRGBPoint(1, 1, 0.8, 0.6);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0);
  opacity->AddPoint(1, 0.3);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
  mapper->SetInputData(image);
#ifdef AVS_CONSUMER_MPI
  vtkNew<vtkMPIController> controller;
  mapper->SetController(controller);
#endif
  int errors = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&errors);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  mapper->AddObserver(vtkCommand::ErrorEvent, count);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(64, 64);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  window->Render();
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, 63, 63, 0, pixels);
  double sum = 0.0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfValues(); ++i)
  {
    sum += pixels->GetValue(i);
  }
  std::cout << "frames " << mapper->GetNumberOfRenderedFrames() << ", errors " << errors
            << ", mean pixel " << sum / pixels->GetNumberOfValues() << "\n";
  return errors == 0 && mapper->GetNumberOfRenderedFrames() == 1 && sum > 0 ? 0 : 1;
}
