#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "PieceAveraging.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <sstream>
#include <string>

// Distributed rendering (the class documentation at WholeExtent; ARCHITECTURE.md, "Distributed
// rendering"): where the input lies in the whole image, and the whole's averaged extinction
// from the pieces' shares.

vtkCxxSetObjectMacro(vtkAVSVolumeMapper, Controller, vtkMultiProcessController);

namespace
{
std::string ExtentText(const int e[6])
{
  std::ostringstream text;
  text << "(" << e[0] << ", " << e[1] << ", " << e[2] << ", " << e[3] << ", " << e[4] << ", "
       << e[5] << ")";
  return text.str();
}
} // namespace

bool vtkAVSVolumeMapper::ResolvePiece(vtkImageData* input, std::string& error)
{
  auto& in = *this->Internal;
  const avs::GridGeometry& g = in.Scene.Scalars.Geometry;
  in.Whole = g;
  in.PieceOffset = { 0, 0, 0 };
  this->LitAsPiece = 0;
  const int* w = this->WholeExtent;
  if (w[0] > w[1] || w[2] > w[3] || w[4] > w[5] || this->GetEffect() != 2)
  {
    return true; // the input is the whole (or nothing is lit across pieces)
  }
  int e[6];
  input->GetExtent(e);
  bool same = true;
  std::array<int, 3> dims{};
  for (int a = 0; a < 3; ++a)
  {
    if (e[2 * a] < w[2 * a] || e[2 * a + 1] > w[2 * a + 1])
    {
      error = "the input's extent " + ExtentText(e) + " is not inside WholeExtent " + ExtentText(w);
      return false;
    }
    same = same && e[2 * a] == w[2 * a] && e[2 * a + 1] == w[2 * a + 1];
    in.PieceOffset[a] = e[2 * a] - w[2 * a];
    // Samples along the axis (points, or cells for cell data): the piece's plus what the whole
    // extent adds.
    dims[a] = g.Dimensions[a] + (w[2 * a + 1] - w[2 * a]) - (e[2 * a + 1] - e[2 * a]);
  }
  if (same)
  {
    return true;
  }
  if (static_cast<double>(dims[0]) * dims[1] * dims[2] > 1e12)
  {
    error = "WholeExtent " + ExtentText(w) + " is too large";
    return false;
  }
  in.Whole = avs::WholeGeometry(g, in.PieceOffset, dims);
  this->LitAsPiece = 1;
  return true;
}

bool vtkAVSVolumeMapper::AverageAcrossPieces(const avs::GridGeometry& lightGrid, std::string& error)
{
  auto& in = *this->Internal;
  const avs::GridGeometry& g = in.Scene.Scalars.Geometry;
  vtkMultiProcessController* controller = this->Controller;
  const int processes = controller ? controller->GetNumberOfProcesses() : 1;
  const avs::IndexBox mine = avs::PieceBox(in.PieceOffset, g.Dimensions);
  // The pieces of lower rank keep the samples they share with this one.
  std::vector<avs::IndexBox> earlier;
  if (processes > 1)
  {
    std::vector<int> boxes(6 * static_cast<std::size_t>(processes));
    if (!controller->AllGather(mine.data(), boxes.data(), 6))
    {
      error = "the pieces' extents could not be gathered over the controller";
      return false;
    }
    const int rank = controller->GetLocalProcessId();
    for (int r = 0; r < rank; ++r)
    {
      avs::IndexBox box;
      std::copy(boxes.begin() + 6 * r, boxes.begin() + 6 * (r + 1), box.begin());
      earlier.push_back(box);
    }
  }
  this->UpdateProgress(0.0);
  avs::Grid share = avs::AverageExtinctionShare(
    in.Extinction, in.PieceOffset, in.Whole, earlier, in.Parameters.AmbientRadius, lightGrid);
  if (processes > 1)
  {
    in.Averaged = avs::Grid(lightGrid, 0.0f);
    if (!controller->AllReduce(share.Values.data(),
          in.Averaged.Values.data(),
          static_cast<vtkIdType>(share.Values.size()),
          vtkCommunicator::SUM_OP))
    {
      error = "the averaged extinction could not be summed over the controller";
      return false;
    }
  }
  else
  {
    in.Averaged = std::move(share);
  }
  this->UpdateProgress(1.0);
  return true;
}
