// A piece lit as a part of the whole (vtkAVSVolumeMapper::WholeExtent; the MPI case is
// ParaView/Testing/TestPVDistributed.py). In one process the rest of the whole is empty space,
// so the upper half of an image whose lower half is empty, rendered with the whole extent, must
// be the whole image's picture: same radius, same light grid, the light volumes read at the
// piece's place in it (point data, cell data, a turned image). Without the whole extent the piece
// is lit as a volume of its own (another radius and light grid): a different picture. The GPU
// and CPU precomputations of the piece agree. An input outside the whole extent is an error with
// nothing drawn; PrintSelf says what it does.
#include "DataTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCellData.h"
#include "vtkMatrix3x3.h"

#include <iostream>
#include <sstream>

namespace
{
// Material in the upper half only (z > 0.1): lumps around a dense blob, so that the lights cast
// shadows inside the piece.
std::array<double, 4> UpperBlob(double x, double y, double z)
{
  if (z < 0.1)
  {
    return { 0, 0, 0, 0 };
  }
  const double r2 = x * x + (y - 0.1) * (y - 0.1) + (z - 0.55) * (z - 0.55);
  const double lumps = 0.5 + 0.5 * std::sin(9 * x) * std::cos(7 * y) * std::sin(8 * z);
  return { 900.0 * std::exp(-r2 / 0.12) * (0.5 + 0.5 * lumps), 0, 0, 0 };
}

// The part of `whole` with z index (of its points) in [k0, k1], keeping VTK's global extent.
vtkSmartPointer<vtkImageData> UpperPiece(vtkImageData* whole, bool cells, int k0)
{
  int e[6];
  whole->GetExtent(e);
  auto piece = vtkSmartPointer<vtkImageData>::New();
  piece->SetExtent(e[0], e[1], e[2], e[3], k0, e[5]);
  piece->SetSpacing(whole->GetSpacing());
  piece->SetOrigin(whole->GetOrigin());
  piece->SetDirectionMatrix(whole->GetDirectionMatrix());
  vtkDataArray* from =
    cells ? whole->GetCellData()->GetScalars() : whole->GetPointData()->GetScalars();
  vtkNew<vtkFloatArray> to;
  to->SetName(from->GetName());
  const int d = cells ? 1 : 0;
  const int nx = e[1] - e[0] + 1 - d, ny = e[3] - e[2] + 1 - d, nz = e[5] - k0 + 1 - d;
  to->SetNumberOfTuples(static_cast<vtkIdType>(nx) * ny * nz);
  const vtkIdType skip = static_cast<vtkIdType>(nx) * ny * (k0 - e[4]);
  for (vtkIdType i = 0; i < to->GetNumberOfTuples(); ++i)
  {
    to->SetValue(i, static_cast<float>(from->GetComponent(i + skip, 0)));
  }
  if (cells)
  {
    piece->GetCellData()->SetScalars(to);
  }
  else
  {
    piece->GetPointData()->SetScalars(to);
  }
  return piece;
}

void Configure(vtkAmbientScatteringVolumeMapper* mapper, vtkImageData* input)
{
  mapper->SetInputData(input);
  mapper->SetSampleDistance(0.01);
  mapper->UseJitteringOff();
  mapper->AutoAdjustSampleDistancesOff();
}
} // namespace

int main(int argc, char* argv[])
{
  int failures = 0;
  const std::string dir = argc > 1 ? argv[1] : ".";
  auto property = MakeTestProperty();
  property->ShadeOff();
  vtkNew<vtkRenderWindow> window;
  PrepareTestWindow(window, 128, 128);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  AddTestLights(renderer);
  PlaceTestCamera(renderer->GetActiveCamera());

  struct Case
  {
    const char* Tag;
    bool Cells;
    bool Turned;
  };
  for (const Case& c :
    { Case{ "points", false, false }, Case{ "cells", true, false }, Case{ "turned", false, true } })
  {
    auto whole = MakeTestImage(40); // extent -20..19 on each axis
    AddArray(whole, "blob", 1, c.Cells, UpperBlob);
    if (c.Cells)
    {
      whole->GetCellData()->SetActiveScalars("blob");
    }
    else
    {
      whole->GetPointData()->SetActiveScalars("blob");
    }
    if (c.Turned)
    {
      const double s = std::sin(0.4), co = std::cos(0.4);
      const double m[9] = { co, 0, s, 0, 1, 0, -s, 0, co };
      whole->SetDirectionMatrix(m);
    }
    auto piece = UpperPiece(whole, c.Cells, 0); // z from index 0 (the middle) up
    int wholeExtent[6];
    whole->GetExtent(wholeExtent);

    vtkNew<vtkAmbientScatteringVolumeMapper> reference;
    Configure(reference, whole);
    vtkNew<vtkAmbientScatteringVolumeMapper> lit;
    Configure(lit, piece);
    lit->SetWholeExtent(wholeExtent);
    vtkNew<vtkAmbientScatteringVolumeMapper> alone;
    Configure(alone, piece);
    vtkNew<TestErrorObserver> errors;
    lit->AddObserver(vtkCommand::ErrorEvent, errors);
    const std::string tag = c.Tag;
    auto expected = RenderVolume(window, renderer, reference, property, dir, "whole_" + tag);
    auto asPiece = RenderVolume(window, renderer, lit, property, dir, "piece_" + tag);
    auto asVolume = RenderVolume(window, renderer, alone, property, dir, "alone_" + tag);
    // The CPU precomputation of the piece (the GPU's oracle) gives the same picture.
    vtkNew<vtkAmbientScatteringVolumeMapper> cpu;
    Configure(cpu, piece);
    cpu->SetWholeExtent(wholeExtent);
    cpu->PrecomputeOnGPUOff();
    auto onCPU = RenderVolume(window, renderer, cpu, property);
    const double same = Psnr(expected, asPiece), other = Psnr(expected, asVolume);
    const double cpuGpu = Psnr(onCPU, asPiece);
    std::cout << tag << ": the piece lit as part of the whole against the whole " << same
              << " dB; lit alone " << other << " dB; its GPU against its CPU precomputation "
              << cpuGpu << " dB\n";
    AVS_CHECK(lit->GetLightVolumesOnGPU() == reference->GetLightVolumesOnGPU());
    AVS_CHECK(cpu->GetLightVolumesOnGPU() == 0);
    AVS_CHECK(cpuGpu >= 60.0);
    AVS_CHECK(errors->Errors == 0);
    AVS_CHECK(Brightness(asPiece) > 1000.0);
    AVS_CHECK(lit->GetLitAsPiece() == 1 && alone->GetLitAsPiece() == 0);
    AVS_CHECK(same >= 45.0);
    AVS_CHECK(other < same - 6.0);
  }

  // An input outside the whole extent: an error, nothing drawn.
  {
    auto whole = MakeTestImage(40);
    AddArray(whole, "blob", 1, false, UpperBlob);
    whole->GetPointData()->SetActiveScalars("blob");
    vtkNew<vtkAmbientScatteringVolumeMapper> mapper;
    Configure(mapper, whole);
    mapper->SetWholeExtent(-20, 19, -20, 19, -20, 10);
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    auto picture = RenderVolume(window, renderer, mapper, property);
    std::cout << "outside the whole extent: " << errors->LastError << "\n";
    AVS_CHECK(errors->Errors == 1);
    AVS_CHECK(errors->LastError.find("is not inside WholeExtent") != std::string::npos);
    AVS_CHECK(Brightness(picture) == 0.0);
    std::ostringstream print;
    mapper->Print(print);
    AVS_CHECK(print.str().find("WholeExtent: (-20, 19, -20, 19, -20, 10)") != std::string::npos);
    AVS_CHECK(print.str().find("LitAsPiece: no") != std::string::npos);
  }
  return failures == 0 ? 0 : 1;
}
