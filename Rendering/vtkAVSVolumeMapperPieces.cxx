#include "vtkAVSVolumeMapper.h"

#include "vtkAVSVolumeMapperInternals.h"

#include "PieceAveraging.h"

#include "vtkAlgorithm.h"
#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <chrono>
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

bool vtkAVSVolumeMapper::AverageAcrossPieces(const avs::GridGeometry& lightGrid,
  avs::Grid& averaged,
  std::string& error)
{
  auto& in = *this->Internal;
  vtkMultiProcessController* controller = this->Controller;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    // The sum UpdatePieceLighting made before the render: rendering never communicates (a
    // collective here would wait for processes whose volume is culled or whose keys differ).
    if (!in.PieceLightingUpdated || in.WholeSum.Values.size() != lightGrid.NumberOfPoints())
    {
      error = "the whole's averaged extinction is not up to date: with a Controller of several "
              "processes, UpdatePieceLighting must run on every process before each render";
      return false;
    }
    averaged = in.WholeSum;
    return true;
  }
  // One process: the rest of the whole is empty space.
  averaged = avs::AverageExtinctionShare(
    this->UpdateExtinction(), in.PieceOffset, in.Whole, {}, in.Parameters.AmbientRadius, lightGrid);
  return true;
}

void vtkAVSVolumeMapper::UpdatePieceLighting(vtkVolume* volume)
{
  const auto start = std::chrono::steady_clock::now();
  this->LastPieceLightingCalls = 0;
  this->LastPieceLightingBytes = 0.0;
  this->LastPieceLightingSeconds = 0.0;
  this->ShareAcrossPieces(volume);
  this->LastPieceLightingSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void vtkAVSVolumeMapper::ShareAcrossPieces(vtkVolume* volume)
{
  auto& in = *this->Internal;
  vtkMultiProcessController* controller = this->Controller;
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    in.PieceLightingUpdated = false;
    return;
  }
  in.PieceLightingUpdated = true; // rendering does not communicate
  // This process's part: a piece of ambient scattering that converts; else nothing (no or an
  // empty input, another lighting model, an input that is the whole): a box of no samples and a
  // share of zeros. Every process takes part in the same calls either way.
  if (vtkAlgorithm* producer = this->GetInputAlgorithm())
  {
    producer->Update();
  }
  std::string ignored; // (reported by the render)
  vtkImageData* input = in.CompositeInput.Resolve(this->GetInputDataObject(0, 0), ignored);
  bool piece = this->GetEffect() == 2 && volume && input && input->GetNumberOfPoints() > 0 &&
    this->PrepareScene(volume) && this->LitAsPiece;
  const avs::GridGeometry& g = in.Scene.Scalars.Geometry;
  avs::GridGeometry lightGrid;
  avs::IndexBox box{ 0, -1, 0, -1, 0, -1 };
  std::vector<double> key;
  if (piece)
  {
    lightGrid = in.Whole.Capped(in.Parameters.LightVolumeMaximumDimension);
    box = avs::PieceBox(in.PieceOffset, g.Dimensions);
    key = { static_cast<double>(in.DataVersion),
      static_cast<double>(in.OpacityVersion),
      in.Parameters.AmbientRadius };
    for (int a = 0; a < 3; ++a)
    {
      key.insert(key.end(),
        { static_cast<double>(lightGrid.Dimensions[a]),
          static_cast<double>(in.Whole.Dimensions[a]),
          static_cast<double>(in.PieceOffset[a]) });
    }
  }
  // Did any piece change, and how long is the light grid (the same on every process that has a
  // piece)?
  std::size_t points = piece ? lightGrid.NumberOfPoints() : 0;
  if (points > static_cast<std::size_t>(VTK_INT_MAX))
  {
    vtkErrorMacro("The light grid of " << points << " points is too large to share.");
    piece = false; // (every process with a piece finds the same)
    points = 0;
    key.clear();
  }
  const int mine[2] = { key != in.ShareKey ? 1 : 0, static_cast<int>(points) };
  int all[2] = { 0, 0 };
  controller->AllReduce(mine, all, 2, vtkCommunicator::MAX_OP);
  this->LastPieceLightingCalls = 1;
  this->LastPieceLightingBytes = sizeof(mine);
  in.ShareKey = key;
  if (!all[0])
  {
    return;
  }
  // The boxes (which piece keeps the samples that pieces share), every share brought up to
  // date, their sum.
  const int processes = controller->GetNumberOfProcesses();
  std::vector<int> boxes(6 * static_cast<std::size_t>(processes));
  controller->AllGather(box.data(), boxes.data(), 6);
  this->LastPieceLightingCalls += 1;
  this->LastPieceLightingBytes += 6 * sizeof(int);
  std::vector<avs::IndexBox> earlier;
  for (int r = 0; r < controller->GetLocalProcessId(); ++r)
  {
    avs::IndexBox other;
    std::copy(boxes.begin() + 6 * r, boxes.begin() + 6 * (r + 1), other.begin());
    if (other[0] <= other[1] && other[2] <= other[3] && other[4] <= other[5])
    {
      earlier.push_back(other);
    }
  }
  if (!piece)
  {
    in.Share = avs::Grid();
  }
  else if (mine[0] || boxes != in.SharedBoxes || in.Share.Values.size() != points)
  {
    this->UpdateExtinction();
    in.Share = avs::AverageExtinctionShare(
      in.Extinction, in.PieceOffset, in.Whole, earlier, in.Parameters.AmbientRadius, lightGrid);
  }
  in.SharedBoxes = boxes;
  const std::size_t length = static_cast<std::size_t>(all[1]);
  const bool agree = !piece || points == length;
  if (!agree)
  {
    vtkErrorMacro("The processes' light grids differ ("
      << points << " points here, " << length
      << " elsewhere): every process needs the same WholeExtent and LightVolumeMaximumDimension.");
  }
  // This process's share is sent as it is (zeros where it has none): the share and the sum are
  // the light grids a process holds.
  std::vector<float> zeros, sum(length, 0.0f);
  const float* send = in.Share.Values.data();
  if (!piece || !agree)
  {
    zeros.assign(length, 0.0f);
    send = zeros.data();
  }
  if (length > 0)
  {
    controller->AllReduce(
      send, sum.data(), static_cast<vtkIdType>(length), vtkCommunicator::SUM_OP);
    this->LastPieceLightingCalls += 1;
    this->LastPieceLightingBytes += static_cast<double>(length) * sizeof(float);
  }
  // A new sum (or none: rendering then reports it) rebuilds what depends on it.
  ++in.SumVersion;
  in.WholeSum = avs::Grid();
  if (piece && agree)
  {
    in.WholeSum = avs::Grid(lightGrid, 0.0f);
    in.WholeSum.Values = std::move(sum);
  }
  else if (piece)
  {
    in.ShareKey.clear(); // shared again at the next call
  }
}
