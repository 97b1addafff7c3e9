#include "vtkAVSCompositeInput.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace
{
// Largest box the merged image may span (the mappers' own limit, vtkAVSDataTranslator).
constexpr double MaximumPoints = 1073741824.0;

// A leaf and its extent on the first leaf's lattice.
struct Leaf
{
  vtkImageData* Image = nullptr;
  int Extent[6] = { 0, -1, 0, -1, 0, -1 };
  unsigned int Index = 0; // its place among the leaves, for messages
};

// The leaves of `tree` that hold a data object, in the tree's order.
std::vector<vtkDataObject*> LeavesOf(vtkDataObjectTree* tree)
{
  std::vector<vtkDataObject*> leaves;
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(tree->NewTreeIterator());
  it->VisitOnlyLeavesOn();
  it->TraverseSubTreeOn();
  it->SkipEmptyNodesOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    leaves.push_back(it->GetCurrentDataObject());
  }
  return leaves;
}

// The leaves of `tree` (empty images skipped), in the tree's order; false where one is not an
// image.
bool CollectLeaves(vtkDataObjectTree* tree, std::vector<Leaf>& leaves, std::string& error)
{
  unsigned int index = 0;
  for (vtkDataObject* block : LeavesOf(tree))
  {
    auto* image = vtkImageData::SafeDownCast(block);
    if (!image)
    {
      error = "leaf " + std::to_string(index) + " is a " + block->GetClassName() +
        "; the blocks must be vtkImageData (resample the others, e.g. with vtkResampleToImage)";
      return false;
    }
    if (image->GetNumberOfPoints() > 0)
    {
      Leaf leaf;
      leaf.Image = image;
      leaf.Index = index;
      image->GetExtent(leaf.Extent);
      leaves.push_back(leaf);
    }
    ++index;
  }
  return true;
}

bool Close(double a, double b)
{
  return std::abs(a - b) <= 1e-6 * std::max({ std::abs(a), std::abs(b), 1e-300 });
}

// Puts every leaf's extent on the first leaf's lattice: the same spacing and direction, and an
// origin that differs from the first's by whole voxels.
bool PlaceLeaves(std::vector<Leaf>& leaves, std::string& error)
{
  vtkImageData* first = leaves.front().Image;
  const double* spacing = first->GetSpacing();
  const double* origin = first->GetOrigin();
  vtkNew<vtkMatrix3x3> inverse;
  inverse->DeepCopy(first->GetDirectionMatrix());
  inverse->Invert();
  for (Leaf& leaf : leaves)
  {
    const double* s = leaf.Image->GetSpacing();
    const double* o = leaf.Image->GetOrigin();
    const double* d = leaf.Image->GetDirectionMatrix()->GetData();
    const double* d0 = first->GetDirectionMatrix()->GetData();
    bool same = true;
    for (int a = 0; a < 3; ++a)
    {
      same = same && Close(s[a], spacing[a]);
    }
    for (int i = 0; i < 9; ++i)
    {
      same = same && std::abs(d[i] - d0[i]) <= 1e-6;
    }
    if (!same)
    {
      std::ostringstream text;
      text << "leaf " << leaf.Index << " has another spacing (" << s[0] << ", " << s[1] << ", "
           << s[2] << ") or direction than leaf " << leaves.front().Index << " (" << spacing[0]
           << ", " << spacing[1] << ", " << spacing[2]
           << "): the blocks must be pieces of one grid (AMR levels are not supported: resample "
              "them onto one grid, e.g. with vtkResampleToImage)";
      error = text.str();
      return false;
    }
    const double shift[3] = { o[0] - origin[0], o[1] - origin[1], o[2] - origin[2] };
    double indexShift[3];
    inverse->MultiplyPoint(shift, indexShift);
    for (int a = 0; a < 3; ++a)
    {
      const double voxels = indexShift[a] / spacing[a];
      const double whole = std::round(voxels);
      if (!std::isfinite(voxels) || std::abs(voxels - whole) > 1e-3 || std::abs(whole) > 1e9)
      {
        std::ostringstream text;
        text << "leaf " << leaf.Index << "'s origin lies " << voxels << " voxels from leaf "
             << leaves.front().Index << "'s along axis " << a
             << ", not a whole number: the blocks must be pieces of one grid";
        error = text.str();
        return false;
      }
      leaf.Extent[2 * a] += static_cast<int>(whole);
      leaf.Extent[2 * a + 1] += static_cast<int>(whole);
    }
  }
  return true;
}

// The counterpart in `attributes` of `array`, an array of the first leaf (its scalars where
// `scalars`): the same name, type and components; unnamed arrays only as the active scalars.
vtkDataArray* Counterpart(vtkDataSetAttributes* attributes, vtkDataArray* array, bool scalars)
{
  const char* name = array->GetName();
  vtkDataArray* other = nullptr;
  if (name && *name)
  {
    other = attributes->GetArray(name);
  }
  else if (scalars)
  {
    other = attributes->GetScalars();
    if (other && other->GetName() && *other->GetName())
    {
      other = nullptr;
    }
  }
  if (other &&
    (other->GetDataType() != array->GetDataType() ||
      other->GetNumberOfComponents() != array->GetNumberOfComponents()))
  {
    other = nullptr;
  }
  return other;
}

// Whether the leaves' boxes (of points, or of cells where `cells`) leave none of `box` empty.
bool Fills(const std::vector<Leaf>& leaves, const int box[6], bool cells, vtkIdType& missing)
{
  const int c = cells ? 1 : 0;
  const vtkIdType nx = box[1] - box[0] + 1 - c, ny = box[3] - box[2] + 1 - c,
                  nz = box[5] - box[4] + 1 - c;
  if (nx <= 0 || ny <= 0 || nz <= 0)
  {
    missing = 0;
    return true;
  }
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(nx * ny * nz), 0);
  for (const Leaf& leaf : leaves)
  {
    const int* e = leaf.Extent;
    for (int z = e[4]; z <= e[5] - c; ++z)
    {
      for (int y = e[2]; y <= e[3] - c; ++y)
      {
        const vtkIdType row = ((z - box[4]) * ny + (y - box[2])) * nx - box[0];
        std::fill(covered.begin() + row + e[0], covered.begin() + row + e[1] - c + 1, 1);
      }
    }
  }
  missing = static_cast<vtkIdType>(std::count(covered.begin(), covered.end(), 0));
  return missing == 0;
}

// Copies the leaves' counterparts of `array` (of the first leaf's point or cell data) into one
// array on `box`.
vtkSmartPointer<vtkDataArray> MergeArray(const std::vector<Leaf>& leaves,
  const std::vector<vtkDataArray*>& sources,
  const int box[6],
  bool cells)
{
  const int c = cells ? 1 : 0;
  const vtkIdType nx = box[1] - box[0] + 1 - c, ny = box[3] - box[2] + 1 - c,
                  nz = box[5] - box[4] + 1 - c;
  vtkSmartPointer<vtkDataArray> merged;
  merged.TakeReference(sources.front()->NewInstance());
  merged->SetName(sources.front()->GetName());
  merged->SetNumberOfComponents(sources.front()->GetNumberOfComponents());
  for (int k = 0; k < sources.front()->GetNumberOfComponents(); ++k)
  {
    if (const char* name = sources.front()->GetComponentName(k))
    {
      merged->SetComponentName(k, name);
    }
  }
  merged->SetNumberOfTuples(std::max<vtkIdType>(0, nx * ny * nz));
  const bool contiguous = merged->HasStandardMemoryLayout();
  const std::size_t tupleBytes =
    static_cast<std::size_t>(merged->GetDataTypeSize()) * merged->GetNumberOfComponents();
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    const int* e = leaves[i].Extent;
    vtkDataArray* source = sources[i];
    const vtkIdType sx = e[1] - e[0] + 1 - c, sy = e[3] - e[2] + 1 - c;
    const bool memcpyRows = contiguous && source->HasStandardMemoryLayout();
    for (int z = e[4]; z <= e[5] - c; ++z)
    {
      for (int y = e[2]; y <= e[3] - c; ++y)
      {
        const vtkIdType from = ((z - e[4]) * sy + (y - e[2])) * sx;
        const vtkIdType to = ((z - box[4]) * ny + (y - box[2])) * nx + (e[0] - box[0]);
        if (memcpyRows)
        {
          std::memcpy(static_cast<char*>(merged->GetVoidPointer(0)) + to * tupleBytes,
            static_cast<const char*>(source->GetVoidPointer(0)) + from * tupleBytes,
            static_cast<std::size_t>(sx) * tupleBytes);
        }
        else
        {
          merged->InsertTuples(to, sx, from, source);
        }
      }
    }
  }
  return merged;
}

// The arrays of the leaves' point (or cell) data that every leaf has, merged into `target`.
void MergeAttributes(const std::vector<Leaf>& leaves,
  const int box[6],
  bool cells,
  vtkDataSetAttributes* target)
{
  auto attributesOf = [cells](vtkImageData* image) -> vtkDataSetAttributes*
  {
    return cells ? static_cast<vtkDataSetAttributes*>(image->GetCellData()) : image->GetPointData();
  };
  vtkDataSetAttributes* first = attributesOf(leaves.front().Image);
  vtkDataArray* firstScalars = first->GetScalars();
  for (int i = 0; i < first->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = first->GetArray(i);
    if (!array)
    {
      continue; // not a data array (strings, ...)
    }
    const bool scalars = array == firstScalars;
    std::vector<vtkDataArray*> sources;
    for (const Leaf& leaf : leaves)
    {
      vtkDataArray* other = Counterpart(attributesOf(leaf.Image), array, scalars);
      vtkIdType expected = 1;
      for (int a = 0; a < 3; ++a)
      {
        expected *= leaf.Extent[2 * a + 1] - leaf.Extent[2 * a] + (cells ? 0 : 1);
      }
      if (!other || other->GetNumberOfTuples() != expected)
      {
        break;
      }
      sources.push_back(other);
    }
    if (sources.size() != leaves.size())
    {
      continue; // not in every leaf: left out
    }
    vtkSmartPointer<vtkDataArray> merged = MergeArray(leaves, sources, box, cells);
    if (scalars)
    {
      target->SetScalars(merged);
    }
    else
    {
      target->AddArray(merged);
    }
  }
}
} // namespace

vtkSmartPointer<vtkImageData> vtkAVSCompositeInput::Merge(vtkDataObjectTree* tree,
  std::string& error)
{
  std::vector<Leaf> leaves;
  if (!CollectLeaves(tree, leaves, error))
  {
    return nullptr;
  }
  if (leaves.empty())
  {
    // Nothing here (a process without a piece): an empty image, as an empty image input.
    return vtkSmartPointer<vtkImageData>::New();
  }
  if (!PlaceLeaves(leaves, error))
  {
    return nullptr;
  }
  if (leaves.size() == 1)
  {
    return leaves.front().Image;
  }
  int box[6] = { VTK_INT_MAX, VTK_INT_MIN, VTK_INT_MAX, VTK_INT_MIN, VTK_INT_MAX, VTK_INT_MIN };
  for (const Leaf& leaf : leaves)
  {
    for (int a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], leaf.Extent[2 * a]);
      box[2 * a + 1] = std::max(box[2 * a + 1], leaf.Extent[2 * a + 1]);
    }
  }
  double points = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    points *= static_cast<double>(box[2 * a + 1]) - box[2 * a] + 1.0;
  }
  std::ostringstream boxText;
  boxText << "(" << box[0] << ", " << box[1] << ", " << box[2] << ", " << box[3] << ", " << box[4]
          << ", " << box[5] << ")";
  if (points > MaximumPoints)
  {
    error = "its " + std::to_string(leaves.size()) + " image blocks span the extent " +
      boxText.str() + ", more than 2^30 points";
    return nullptr;
  }
  vtkIdType missing = 0;
  const bool cellArrays = leaves.front().Image->GetCellData()->GetNumberOfArrays() > 0;
  if (!Fills(leaves, box, false, missing) || (cellArrays && !Fills(leaves, box, true, missing)))
  {
    error = "its " + std::to_string(leaves.size()) + " image blocks leave " +
      std::to_string(missing) + " " + (cellArrays ? "points or cells" : "points") +
      " of the extent they span, " + boxText.str() +
      ", empty: the blocks must be pieces of one box (split across processes, give each "
      "process pieces that make a box)";
    return nullptr;
  }
  vtkImageData* first = leaves.front().Image;
  auto merged = vtkSmartPointer<vtkImageData>::New();
  merged->SetExtent(box);
  merged->SetSpacing(first->GetSpacing());
  merged->SetOrigin(first->GetOrigin());
  merged->SetDirectionMatrix(first->GetDirectionMatrix());
  MergeAttributes(leaves, box, false, merged->GetPointData());
  MergeAttributes(leaves, box, true, merged->GetCellData());
  merged->GetFieldData()->ShallowCopy(first->GetFieldData());
  return merged;
}

vtkImageData* vtkAVSCompositeInput::Resolve(vtkDataObject* input, std::string& error)
{
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    this->Release();
    return image;
  }
  auto* tree = vtkDataObjectTree::SafeDownCast(input);
  if (!tree)
  {
    this->Release();
    error.clear();
    return nullptr;
  }
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> key{ { tree, tree->GetMTime() } };
  for (vtkDataObject* leaf : LeavesOf(tree))
  {
    key.emplace_back(leaf, leaf->GetMTime());
  }
  if (key != this->Key)
  {
    this->Merged = nullptr;
    this->Error.clear();
    this->Merged = Merge(tree, this->Error);
    this->Key = std::move(key);
  }
  error = this->Error;
  return this->Merged;
}

void vtkAVSCompositeInput::Release()
{
  this->Merged = nullptr;
  this->Key.clear();
  this->Error.clear();
}
