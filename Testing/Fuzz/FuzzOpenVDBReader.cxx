// Fuzz target: vtkOpenVDBImageReader on a file holding the input bytes.
//
// The reader must either give a volume (scalars on every point, all finite) and no error, or
// an error and an empty output: never a partial volume, never an exception or a crash. The
// options (level sets to fog volumes, vector components, the user box) follow the input's
// size, so that one corpus covers them. MaximumNumberOfVoxels is small, as a fuzzer needs many
// runs a second; the memory guard is what keeps corrupt boxes cheap.
#include "FuzzInput.h"
#include "vtkOpenVDBImageReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Errors; }
  int Errors = 0;
};

std::string FilePath()
{
  const char* folder = std::getenv("TMPDIR");
  return std::string(folder && *folder ? folder : "/tmp") + "/avs-fuzz-vdb-" +
    std::to_string(static_cast<long>(getpid())) + ".vdb";
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const std::string path = FilePath();
  FuzzQuietVTK(); // AVS_FUZZ_VERBOSE=1: VTK's messages are shown
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  vtkNew<vtkOpenVDBImageReader> reader;
  vtkNew<ErrorCounter> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->SetMaximumNumberOfVoxels(4096);
  reader->SetLevelSetToFogVolume(size & 1);
  reader->SetVectorMode(
    size & 2 ? vtkOpenVDBImageReader::VECTOR_COMPONENTS : vtkOpenVDBImageReader::VECTOR_MAGNITUDE);
  if (size % 7 == 0)
  {
    reader->UseBoundingBoxOn();
    reader->SetBoundingBox(-3, 12, -3, 12, -3, 12);
  }
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  for (int i = 0; i < reader->GetNumberOfGrids(); ++i)
  {
    double voxel[3];
    int box[6];
    reader->GetGridVoxelSize(i, voxel);
    reader->GetGridBoundingBox(i, box);
    FUZZ_CHECK(reader->GetGridName(i) && reader->GetGridValueType(i) && reader->GetGridClass(i));
  }
  const vtkIdType points = image->GetNumberOfPoints();
  if (errors->Errors > 0)
  {
    FUZZ_CHECK(points == 0 || image->GetPointData()->GetScalars() == nullptr);
    return 0;
  }
  FUZZ_CHECK(points > 0);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  FUZZ_CHECK(scalars && scalars->GetNumberOfTuples() == points);
  FUZZ_CHECK(points <= 4096);
  for (vtkIdType i = 0; i < points; ++i)
  {
    for (int c = 0; c < scalars->GetNumberOfComponents(); ++c)
    {
      FUZZ_CHECK(std::isfinite(scalars->GetComponent(i, c)));
    }
  }
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  for (int a = 0; a < 3; ++a)
  {
    FUZZ_CHECK(std::isfinite(spacing[a]) && spacing[a] > 0.0 && std::isfinite(origin[a]));
  }
  return 0;
}
