// Empty-space skipping's grid (OccupancyGrid.h): each cell's value ranges are those of the
// lattice points its samples can read, nothing a sample reads in an empty cell has sigma_t > 0
// (single and independent components, NaN voxels, label maps, narrow transfer-function bands
// that no voxel's value but an interpolated one falls in), and a volume with material in a
// corner leaves the rest empty.
#include "OccupancyGrid.h"
#include "Random.h"
#include "ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

using namespace avs;

namespace
{
Grid Field(const std::array<int, 3>& d, const std::function<double(int, int, int)>& f)
{
  GridGeometry g;
  g.Dimensions = d;
  Grid grid(g);
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        grid.At(i, j, k) = static_cast<float>(f(i, j, k));
      }
  return grid;
}

// Reads the scene's components (0: the scalars) as the mappers' uploads do.
ValueRangeGrid RangesOf(const VolumeScene& scene, int cellSize)
{
  const int components = 1 + static_cast<int>(scene.Medium.Components.size());
  return ValueRangeGrid(
    scene.Scalars.Geometry.Dimensions,
    components,
    cellSize,
    [&scene](int c, std::size_t begin, std::size_t end, float* out)
    {
      const Grid& g = c == 0 ? scene.Scalars : scene.Medium.Components[c - 1].Values;
      std::copy(g.Values.begin() + begin, g.Values.begin() + end, out);
    },
    scene.Medium.Validity.Values);
}

// A table over [0, 1] that is 0 except for a narrow band around `centre`.
TransferFunction Band(double centre, double width, int nodes = 256)
{
  TransferFunction tf;
  for (int n = 0; n < nodes; ++n)
  {
    const double s = n / (nodes - 1.0);
    tf.Opacity.push_back(std::abs(s - centre) < width ? 0.7f : 0.0f);
    tf.Color.push_back({ 1.0f, 1.0f, 1.0f });
  }
  return tf;
}

// Samples at random points of each empty cell, through the CPU classifier (the GPU's twin):
// none may have sigma_t > 0. Returns the number of empty cells checked.
int ExpectEmptyCellsEmpty(const VolumeScene& scene, const ValueRangeGrid& ranges, int samples)
{
  const std::vector<unsigned char> occupied = Occupancy(ranges, Classifier(scene));
  const Classifier classifier(scene);
  const auto& cells = ranges.Cells();
  const auto& d = scene.Scalars.Geometry.Dimensions;
  const double B = ranges.CellSize();
  Random random(7);
  int checked = 0;
  for (int ck = 0; ck < cells[2]; ++ck)
    for (int cj = 0; cj < cells[1]; ++cj)
      for (int ci = 0; ci < cells[0]; ++ci)
      {
        const std::size_t id = (static_cast<std::size_t>(ck) * cells[1] + cj) * cells[0] + ci;
        if (occupied[id])
        {
          continue;
        }
        ++checked;
        const int c[3] = { ci, cj, ck };
        for (int s = 0; s < samples; ++s)
        {
          Vec3 p;
          for (int a = 0; a < 3; ++a)
          {
            // The cell's owned indices, half a voxel past its faces (the GPU's rounding), in
            // the box.
            const double lo = std::max(0.0, c[a] * B - 0.5);
            const double hi = std::min(d[a] - 1.0, (c[a] + 1) * B + 0.5);
            p[a] = lo + (hi - lo) * random.Uniform();
          }
          EXPECT_EQ(classifier.AtIndex(p).SigmaT, 0.0)
            << "a sample in the empty cell (" << ci << ", " << cj << ", " << ck << ") at (" << p.x
            << ", " << p.y << ", " << p.z << ")";
        }
      }
  return checked;
}
} // namespace

TEST(OccupancyGrid, RangesAreThoseOfTheLatticePointsTheCellsSamplesRead)
{
  Random random(3);
  for (const int cellSize : { 1, 3, 8 })
  {
    const std::array<int, 3> d{ 17, 9, 12 };
    VolumeScene scene;
    scene.Scalars = Field(d, [&](int, int, int) { return random.Uniform(); });
    scene.Medium.Validity = Field(d, [&](int, int, int) { return random.Uniform() < 0.1 ? 0 : 1; });
    const ValueRangeGrid ranges = RangesOf(scene, cellSize);
    const auto& cells = ranges.Cells();
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(cells[a], (d[a] + cellSize - 1) / cellSize);
    }
    for (int ck = 0; ck < cells[2]; ++ck)
      for (int cj = 0; cj < cells[1]; ++cj)
        for (int ci = 0; ci < cells[0]; ++ci)
        {
          float lo = std::numeric_limits<float>::infinity(), hi = -lo;
          const int c[3] = { ci, cj, ck };
          int b[3], e[3];
          for (int a = 0; a < 3; ++a)
          {
            b[a] = std::max(0, c[a] * cellSize - 1);
            e[a] = std::min(d[a] - 1, (c[a] + 1) * cellSize + 1);
          }
          for (int k = b[2]; k <= e[2]; ++k)
            for (int j = b[1]; j <= e[1]; ++j)
              for (int i = b[0]; i <= e[0]; ++i)
              {
                if (scene.Medium.Validity.At(i, j, k) > 0.0f)
                {
                  lo = std::min(lo, scene.Scalars.At(i, j, k));
                  hi = std::max(hi, scene.Scalars.At(i, j, k));
                }
              }
          const std::size_t id = (static_cast<std::size_t>(ck) * cells[1] + cj) * cells[0] + ci;
          EXPECT_EQ(ranges.Low(id, 0), lo);
          EXPECT_EQ(ranges.High(id, 0), hi);
        }
  }
}

TEST(OccupancyGrid, NoSampleInAnEmptyCellHasExtinction)
{
  // A smooth blob whose values cross a narrow band of the table only between lattice points in
  // places: an interpolated sample can have extinction where no voxel does.
  const std::array<int, 3> d{ 40, 33, 36 };
  VolumeScene scene;
  scene.Scalars = Field(d,
    [](int i, int j, int k)
    {
      const double r =
        std::sqrt((i - 14.0) * (i - 14.0) + (j - 16.0) * (j - 16.0) + (k - 15.0) * (k - 15.0));
      return std::max(0.0, 1.0 - r / 12.0);
    });
  scene.UnitDistance = 1.0;
  for (const double centre : { 0.3, 0.55, 0.9 })
  {
    scene.Transfer = Band(centre, 0.004);
    const int empty = ExpectEmptyCellsEmpty(scene, RangesOf(scene, 4), 200);
    EXPECT_GT(empty, 0) << "the band at " << centre << " leaves cells empty";
  }
}

TEST(OccupancyGrid, NaNVoxelsIndependentComponentsAndLabelMapsStayConservative)
{
  const std::array<int, 3> d{ 24, 24, 24 };
  Random random(11);
  VolumeScene scene;
  scene.Scalars = Field(d, [](int i, int, int) { return i < 10 ? 0.05 : 0.6; });
  scene.Transfer = Band(0.6, 0.05);
  scene.UnitDistance = 1.0;
  // NaN voxels among the material, whose neighbours' samples still interpolate it.
  scene.Medium.Validity = Field(d, [&](int, int, int) { return random.Uniform() < 0.2 ? 0 : 1; });
  for (std::size_t v = 0; v < scene.Scalars.Values.size(); ++v)
  {
    scene.Scalars.Values[v] *= scene.Medium.Validity.Values[v];
  }
  EXPECT_GT(ExpectEmptyCellsEmpty(scene, RangesOf(scene, 4), 100), 0);

  // A second, independent component with material where the first has none.
  scene.Medium.Validity = Grid();
  scene.Medium.Mode = ComponentMode::Independent;
  MediumComponent second;
  second.Values = Field(d, [](int, int j, int) { return j > 18 ? 1.0 : 0.0; });
  second.Transfer = TransferFunction::Ramp(0.5, 1.0, 0.8, { 1, 1, 1 });
  scene.Medium.Components = { second };
  const ValueRangeGrid two = RangesOf(scene, 4);
  EXPECT_EQ(two.Components(), 2);
  EXPECT_GT(ExpectEmptyCellsEmpty(scene, two, 100), 0);
  // Its weight 0 takes it out.
  scene.Medium.Components[0].Weight = 0.0;
  const std::vector<unsigned char> weighted = Occupancy(two, Classifier(scene));
  scene.Medium.Components[0].Weight = 1.0;
  EXPECT_GT(EmptyFraction(weighted), EmptyFraction(Occupancy(two, Classifier(scene))));

  // A label map whose label 1 gives opacity to values the unlabelled function leaves empty.
  scene.Medium = MediumOptions();
  scene.Medium.Mask = MaskType::LabelMap;
  scene.Medium.MaskValues = Field(d, [](int, int, int k) { return k < 12 ? 1.0 : 0.0; });
  scene.Medium.Labels = { TransferFunction::Ramp(0.0, 0.1, 0.5, { 1, 0, 0 }) };
  const ValueRangeGrid one = RangesOf(scene, 4);
  const int empty = ExpectEmptyCellsEmpty(scene, one, 100);
  EXPECT_EQ(empty, 0) << "the label's function reaches the values 0.05: no cell is empty";
}

TEST(OccupancyGrid, MaterialInACornerLeavesTheRestEmpty)
{
  const std::array<int, 3> d{ 64, 64, 64 };
  VolumeScene scene;
  scene.Scalars =
    Field(d, [](int i, int j, int k) { return i < 16 && j < 16 && k < 16 ? 1.0 : 0.0; });
  scene.Transfer = TransferFunction::Ramp(0.1, 1.0, 0.5, { 1, 1, 1 });
  const ValueRangeGrid ranges = RangesOf(scene, 8);
  const std::vector<unsigned char> occupied = Occupancy(ranges, Classifier(scene));
  // The corner's 2^3 cells and their neighbours that read the voxel layer 16 (one voxel to
  // spare): 3^3 of 8^3 cells.
  EXPECT_DOUBLE_EQ(EmptyFraction(occupied), 1.0 - 27.0 / 512.0);
  // A transfer function without opacity empties everything; one with opacity at 0 nothing.
  scene.Transfer = TransferFunction::Constant(0.0, { 1, 1, 1 });
  EXPECT_DOUBLE_EQ(EmptyFraction(Occupancy(ranges, Classifier(scene))), 1.0);
  scene.Transfer = TransferFunction::Constant(0.2, { 1, 1, 1 });
  EXPECT_DOUBLE_EQ(EmptyFraction(Occupancy(ranges, Classifier(scene))), 0.0);
}

TEST(OccupancyGrid, MajorantsBoundEverySampleOfTheirCellAndGiveTheOccupancy)
{
  // The GPU path tracer's majorants: no sample its walk can take in a cell (the cell's owned
  // indices and half a voxel past them) has more extinction than the cell's majorant, and the
  // occupancy is where the majorant is above 0.
  Random random(11);
  const std::array<int, 3> d{ 23, 18, 20 };
  VolumeScene scene;
  scene.Scalars = Field(d, [&](int, int, int) { return random.Uniform(); });
  scene.UnitDistance = 0.7;
  for (const double centre : { 0.2, 0.5, 0.85 })
  {
    scene.Transfer = Band(centre, 0.05);
    const ValueRangeGrid ranges = RangesOf(scene, 4);
    const Classifier classifier(scene);
    const std::vector<float> majorants = Majorants(ranges, classifier);
    const std::vector<unsigned char> occupied = Occupancy(ranges, classifier);
    ASSERT_EQ(majorants.size(), occupied.size());
    const auto& cells = ranges.Cells();
    const double B = ranges.CellSize();
    int positive = 0;
    for (int ck = 0; ck < cells[2]; ++ck)
      for (int cj = 0; cj < cells[1]; ++cj)
        for (int ci = 0; ci < cells[0]; ++ci)
        {
          const std::size_t id = (static_cast<std::size_t>(ck) * cells[1] + cj) * cells[0] + ci;
          EXPECT_EQ(occupied[id] != 0, majorants[id] > 0.0f);
          positive += majorants[id] > 0.0f ? 1 : 0;
          const int c[3] = { ci, cj, ck };
          for (int s = 0; s < 50; ++s)
          {
            Vec3 p;
            for (int a = 0; a < 3; ++a)
            {
              const double lo = std::max(0.0, c[a] * B - 0.5);
              const double hi = std::min(d[a] - 1.0, (c[a] + 1) * B + 0.5);
              p[a] = lo + (hi - lo) * random.Uniform();
            }
            EXPECT_LE(classifier.AtIndex(p).SigmaT, majorants[id])
              << "cell (" << ci << ", " << cj << ", " << ck << ")";
          }
        }
    EXPECT_GT(positive, 0);
  }
}
