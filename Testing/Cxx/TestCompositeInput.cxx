// Composite inputs: image blocks of one grid in a vtkMultiBlockDataSet (nested), a
// vtkPartitionedDataSet or a vtkPartitionedDataSetCollection, through SetInputData and
// SetInputConnection, drawn by the three mappers as the one image they make (the same picture
// as the image itself: light crosses the blocks), point and cell data, blocks that share their
// faces or not, blocks placed by extent or by origin, a block changed in place; and what cannot
// be drawn (an error naming it, nothing drawn): a gap, another spacing, a block off the grid, a
// block that is not an image, an AMR dataset. The CPU reference (vtkVolumeReferenceRenderer) takes
// the same trees.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCellData.h"
#include "vtkDataObjectTree.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkFloatArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkOverlappingAMR.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPolyData.h"
#include "vtkShortArray.h"
#include "vtkTrivialProducer.h"
#include "vtkVolumeReferenceRenderer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{

// The part of `whole` on `extent` (a copy).
vtkSmartPointer<vtkImageData> Piece(vtkImageData* whole, const std::vector<int>& extent)
{
  auto piece = vtkSmartPointer<vtkImageData>::New();
  piece->DeepCopy(whole);
  piece->Crop(extent.data());
  return piece;
}

// `whole` (extent -16..15 on each axis) in eight blocks, split at 0 on each axis; `shared`:
// neighbours share the points of their common face (else each point is in one block).
std::vector<vtkSmartPointer<vtkImageData>> Blocks(vtkImageData* whole, bool shared)
{
  int e[6];
  whole->GetExtent(e);
  std::vector<vtkSmartPointer<vtkImageData>> blocks;
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        const int low[3] = { i ? 0 : e[0], j ? 0 : e[2], k ? 0 : e[4] };
        const int high[3] = {
          i ? e[1] : (shared ? 0 : -1), j ? e[3] : (shared ? 0 : -1), k ? e[5] : (shared ? 0 : -1)
        };
        blocks.push_back(Piece(whole, { low[0], high[0], low[1], high[1], low[2], high[2] }));
      }
    }
  }
  return blocks;
}

// The same blocks, each with extent starting at 0 and its origin moved to where it lies.
void PlaceByOrigin(std::vector<vtkSmartPointer<vtkImageData>>& blocks)
{
  for (auto& block : blocks)
  {
    int e[6];
    block->GetExtent(e);
    double origin[3];
    for (int a = 0; a < 3; ++a)
    {
      origin[a] = block->GetOrigin()[a] + e[2 * a] * block->GetSpacing()[a];
    }
    block->SetExtent(0, e[1] - e[0], 0, e[3] - e[2], 0, e[5] - e[4]);
    block->SetOrigin(origin);
  }
}

// `whole` with the cell-centred values of MakeTestVolume's ball as cell scalars (33^3 points).
vtkSmartPointer<vtkImageData> CellVolume()
{
  auto points = MakeTestVolume(32);
  auto cells = vtkSmartPointer<vtkImageData>::New();
  cells->SetExtent(-16, 16, -16, 16, -16, 16);
  cells->SetSpacing(points->GetSpacing());
  cells->SetOrigin(points->GetOrigin());
  vtkNew<vtkShortArray> values;
  values->DeepCopy(points->GetPointData()->GetScalars());
  values->SetName("cell values");
  cells->GetCellData()->SetScalars(values);
  return cells;
}
} // namespace

int main(int, char*[])
{
  int failures = 0;
  auto whole = MakeTestVolume(32);

  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  for (vtkAVSVolumeMapper* mapper : { static_cast<vtkAVSVolumeMapper*>(as),
         static_cast<vtkAVSVolumeMapper*>(ao),
         static_cast<vtkAVSVolumeMapper*>(ea) })
  {
    const std::string name = mapper->GetClassName();
    const bool lit = mapper != ea.Get();
    TestScene scene(mapper, 64);
    vtkNew<TestErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->SetInputData(whole);
    const auto reference = scene.Render();
    double wholeBounds[6];
    mapper->GetBounds(wholeBounds);
    AVS_CHECK(Brightness(reference) > 0.0);

    // The same picture from the blocks (PSNR printed; identical where the blocks make the image).
    auto expectSame = [&](const std::string& what, vtkImageData* expected)
    {
      errors->Clear();
      const auto picture = scene.Render();
      const double psnr = Psnr(picture, expected);
      std::cout << name << ", " << what << ": " << psnr << " dB against the one image\n";
      if (errors->Errors > 0 || psnr < 45.0)
      {
        std::cerr << name << ", " << what << ": " << psnr << " dB, error '" << errors->LastError
                  << "'\n";
        ++failures;
      }
      double bounds[6];
      mapper->GetBounds(bounds);
      for (int i = 0; i < 6; ++i)
      {
        AVS_CHECK(std::abs(bounds[i] - wholeBounds[i]) < 1e-9);
      }
    };

    // A vtkMultiBlockDataSet (blocks sharing their faces, in two levels) by SetInputData.
    {
      auto blocks = Blocks(whole, true);
      vtkNew<vtkMultiBlockDataSet> tree;
      vtkNew<vtkMultiBlockDataSet> inner;
      for (std::size_t i = 0; i < blocks.size(); ++i)
      {
        if (i < 4)
        {
          tree->SetBlock(static_cast<unsigned int>(i), blocks[i]);
        }
        else
        {
          inner->SetBlock(static_cast<unsigned int>(i - 4), blocks[i]);
        }
      }
      tree->SetBlock(4, inner);
      mapper->SetInputData(tree);
      expectSame("vtkMultiBlockDataSet, SetInputData", reference);
    }

    // A vtkPartitionedDataSet through a producer (SetInputConnection), blocks that do not share
    // their faces.
    {
      auto blocks = Blocks(whole, false);
      vtkNew<vtkPartitionedDataSet> partitions;
      for (std::size_t i = 0; i < blocks.size(); ++i)
      {
        partitions->SetPartition(static_cast<unsigned int>(i), blocks[i]);
      }
      vtkNew<vtkTrivialProducer> producer;
      producer->SetOutput(partitions);
      mapper->SetInputConnection(producer->GetOutputPort());
      expectSame("vtkPartitionedDataSet, SetInputConnection", reference);

      // A block changed in place: drawn again with the change (the whole changed the same way).
      vtkDataArray* values = blocks[0]->GetPointData()->GetScalars();
      for (vtkIdType t = 0; t < values->GetNumberOfTuples(); ++t)
      {
        values->SetTuple1(t, 900.0);
      }
      values->Modified();
      auto changed = vtkSmartPointer<vtkImageData>::New();
      changed->DeepCopy(whole);
      int e[6];
      blocks[0]->GetExtent(e);
      for (int z = e[4]; z <= e[5]; ++z)
        for (int y = e[2]; y <= e[3]; ++y)
          for (int x = e[0]; x <= e[1]; ++x)
          {
            int ijk[3] = { x, y, z };
            changed->GetPointData()->GetScalars()->SetTuple1(changed->ComputePointId(ijk), 900.0);
          }
      mapper->SetInputData(changed);
      const auto changedReference = scene.Render();
      AVS_CHECK(Psnr(changedReference, reference) < 40.0); // the change shows
      mapper->SetInputConnection(producer->GetOutputPort());
      expectSame("a block changed in place", changedReference);
      mapper->SetInputConnection(nullptr);
    }

    if (lit) // (the drawing is the mappers' shared code: once is enough for the rest)
    {
      // A vtkPartitionedDataSetCollection of blocks placed by their origins, one empty partition.
      auto blocks = Blocks(whole, true);
      PlaceByOrigin(blocks);
      vtkNew<vtkPartitionedDataSetCollection> collection;
      for (unsigned int p = 0; p < 2; ++p)
      {
        vtkNew<vtkPartitionedDataSet> partitions;
        for (unsigned int i = 0; i < 4; ++i)
        {
          partitions->SetPartition(i, blocks[4 * p + i]);
        }
        partitions->SetPartition(4, vtkNew<vtkImageData>());
        collection->SetPartitionedDataSet(p, partitions);
      }
      mapper->SetInputData(collection);
      expectSame("vtkPartitionedDataSetCollection, blocks placed by origin", reference);

      // One block: drawn as the image itself.
      vtkNew<vtkMultiBlockDataSet> one;
      one->SetBlock(0, whole);
      mapper->SetInputData(one);
      expectSame("one block", reference);

      // Cell data in blocks that share their faces' points.
      auto cells = CellVolume();
      mapper->SetInputData(cells);
      const auto cellReference = scene.Render();
      AVS_CHECK(Brightness(cellReference) > 0.0);
      auto cellBlocks = Blocks(cells, true);
      vtkNew<vtkMultiBlockDataSet> cellTree;
      for (std::size_t i = 0; i < cellBlocks.size(); ++i)
      {
        cellTree->SetBlock(static_cast<unsigned int>(i), cellBlocks[i]);
      }
      mapper->SetInputData(cellTree);
      errors->Clear();
      const auto cellPicture = scene.Render();
      const double psnr = Psnr(cellPicture, cellReference);
      std::cout << name << ", cell data in blocks: " << psnr << " dB against the one image\n";
      AVS_CHECK(errors->Errors == 0 && psnr >= 45.0);
    }

    // What cannot be drawn: an error naming it, nothing drawn.
    auto expectError = [&](vtkDataObject* input, const std::string& text)
    {
      errors->Clear();
      mapper->SetInputDataObject(input);
      const int frames = mapper->GetNumberOfRenderedFrames();
      const auto picture = scene.Render();
      if (errors->Errors == 0 || errors->LastError.find(text) == std::string::npos)
      {
        std::cerr << name << ": expected an error with '" << text << "', got '" << errors->LastError
                  << "'\n";
        ++failures;
      }
      AVS_CHECK(Brightness(picture) == 0.0);
      AVS_CHECK(mapper->GetNumberOfRenderedFrames() == frames);
    };
    {
      auto blocks = Blocks(whole, true);
      vtkNew<vtkMultiBlockDataSet> gap; // one of eight left out
      for (unsigned int i = 0; i < 7; ++i)
      {
        gap->SetBlock(i, blocks[i]);
      }
      expectError(gap,
        "image blocks leave 3375 points of the extent they span, (-16, 15, -16, "
        "15, -16, 15), empty");
      // GetInput (what ParaView asks before rendering) reports it too, once.
      errors->Clear();
      AVS_CHECK(mapper->GetInput() == nullptr);
      AVS_CHECK(errors->Errors == 1 && errors->LastError.find("3375 points") != std::string::npos);
      AVS_CHECK(mapper->GetInput() == nullptr);
      AVS_CHECK(errors->Errors == 1);

      vtkNew<vtkMultiBlockDataSet> spacing; // an AMR-like finer block
      spacing->SetBlock(0, blocks[0]);
      auto finer = Piece(whole, { 0, 15, 0, 15, 0, 15 });
      finer->SetSpacing(0.025, 0.025, 0.03);
      spacing->SetBlock(1, finer);
      expectError(spacing, "leaf 1 has another spacing");

      vtkNew<vtkMultiBlockDataSet> offGrid; // a block half a voxel off
      offGrid->SetBlock(0, blocks[0]);
      auto shifted = Piece(whole, { 0, 15, -16, 0, -16, 0 });
      shifted->SetOrigin(0.025, 0.0, 0.0);
      offGrid->SetBlock(1, shifted);
      expectError(offGrid, "not a whole number");

      vtkNew<vtkMultiBlockDataSet> polygons;
      polygons->SetBlock(0, blocks[0]);
      polygons->SetBlock(1, vtkNew<vtkPolyData>());
      expectError(polygons, "leaf 1 is a vtkPolyData");

      vtkNew<vtkMultiBlockDataSet> nothing; // no block: as an empty image
      nothing->SetBlock(0, vtkNew<vtkImageData>());
      expectError(nothing, "empty");

      vtkNew<vtkOverlappingAMR> amr; // (VTK's pipeline says first that the mapper cannot take it)
      // (Since VTK 9.5 AMR datasets are trees: an empty one is then an empty input.)
      expectError(
        amr, vtkDataObjectTree::SafeDownCast(amr) ? "empty" : "not a tree of image blocks");
    }
    mapper->SetInputData(static_cast<vtkImageData*>(nullptr));
  }

  // The CPU reference takes the same trees: the same radiance as from the image itself, and the
  // same refusal of a gap.
  {
    vtkNew<vtkRenderer> renderer;
    AddTestLights(renderer);
    PlaceTestCamera(renderer->GetActiveCamera());
    vtkNew<vtkVolumeReferenceRenderer> reference;
    vtkNew<TestErrorObserver> errors;
    reference->AddObserver(vtkCommand::ErrorEvent, errors);
    reference->SetVolumeProperty(MakeTestProperty());
    reference->SetRenderer(renderer);
    reference->SetImageSize(24, 24);
    reference->SetInputData(whole);
    reference->Update();
    vtkNew<vtkFloatArray> expected;
    expected->DeepCopy(reference->GetOutput()->GetPointData()->GetArray("Radiance"));
    auto blocks = Blocks(whole, false);
    vtkNew<vtkPartitionedDataSet> partitions;
    for (std::size_t i = 0; i < blocks.size(); ++i)
    {
      partitions->SetPartition(static_cast<unsigned int>(i), blocks[i]);
    }
    reference->SetInputData(partitions);
    reference->Update();
    vtkDataArray* radiance = reference->GetOutput()->GetPointData()->GetArray("Radiance");
    AVS_CHECK(errors->Errors == 0 && radiance &&
      radiance->GetNumberOfValues() == expected->GetNumberOfValues());
    double largest = 0.0, sum = 0.0;
    for (vtkIdType v = 0; radiance && v < radiance->GetNumberOfValues(); ++v)
    {
      largest = std::max(
        largest, std::abs(radiance->GetVariantValue(v).ToDouble() - expected->GetValue(v)));
      sum += expected->GetValue(v);
    }
    std::cout << "vtkVolumeReferenceRenderer, vtkPartitionedDataSet: largest radiance difference "
              << largest << " (radiance sum " << sum << ")\n";
    AVS_CHECK(sum > 0.0 && largest == 0.0);
    vtkNew<vtkMultiBlockDataSet> gap;
    for (unsigned int i = 0; i < 7; ++i)
    {
      gap->SetBlock(i, blocks[i]);
    }
    reference->SetInputData(gap);
    reference->Update();
    AVS_CHECK(
      errors->Errors == 1 && errors->LastError.find("image blocks leave") != std::string::npos);
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
