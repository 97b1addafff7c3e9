/**
 * @class   vtkAVSCompositeInput
 * @brief   a composite input's image blocks as the one image the mappers draw (private)
 *
 * The mappers take, besides a vtkImageData, a vtkDataObjectTree (vtkMultiBlockDataSet,
 * vtkPartitionedDataSet, vtkPartitionedDataSetCollection) whose non-empty leaves are
 * vtkImageData pieces of one grid: the same spacing and direction, origins on one lattice (the
 * leaves' own extents, or origins that differ by whole voxels). Their point and cell arrays that
 * every leaf has (the same name, type and components; unnamed ones only as every leaf's active
 * scalars) are copied into one image spanning the box the leaves fill, which is then lit and
 * drawn as any image: light crosses the blocks as if they had never been split. One leaf is used
 * as it is (no copy); a tree without a non-empty leaf gives an empty image (as an empty image
 * input). Kept until the tree or a leaf changes (their MTimes).
 *
 * What is refused, with a message naming it: a leaf that is not a vtkImageData (polygons,
 * rectilinear or unstructured grids), leaves of other spacings or directions (AMR levels) or
 * off the first leaf's lattice, leaves that leave part of their box empty, a box of more than
 * 2^30 points. Composite datasets that are not trees (vtkOverlappingAMR and
 * vtkNonOverlappingAMR before VTK 9.5; trees since, whose levels' spacings then differ) are not
 * accepted by the mappers' input port.
 */
#ifndef vtkAVSCompositeInput_h
#define vtkAVSCompositeInput_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <utility>
#include <vector>

class vtkDataObject;
class vtkDataObjectTree;
class vtkImageData;

class vtkAVSCompositeInput
{
public:
  /// The image to draw for `input`: `input` itself where it is a vtkImageData; for a
  /// vtkDataObjectTree the merged image of its leaves (kept while they do not change); nullptr
  /// where it is neither or the leaves cannot be merged (`error` says why; empty where `input`
  /// is neither a vtkImageData nor a tree).
  vtkImageData* Resolve(vtkDataObject* input, std::string& error);

  /// Drops the merged image.
  void Release();

  /// The leaves of `tree` merged into one image (the leaf itself where there is one), or nullptr
  /// with the reason in `error`.
  static vtkSmartPointer<vtkImageData> Merge(vtkDataObjectTree* tree, std::string& error);

private:
  vtkSmartPointer<vtkImageData> Merged;
  /// What Merged (or Error) was made from: the tree and its leaves with their MTimes.
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> Key;
  std::string Error;
};

#endif
