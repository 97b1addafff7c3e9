/**
 * @class   vtkOpenVDBImageReader
 * @brief   reads one grid of an OpenVDB file into vtkImageData
 *
 * Reads a grid of a `.vdb` file (OpenVDB 10, older file versions included) into image data with
 * point scalars, ready for the volume mappers:
 *
 * - the grid: GridName, default `density` if the file has it, else the first scalar grid; after
 *   UpdateInformation, GetNumberOfGrids(), GetGridName(i), GetGridClass(i), GetGridValueType(i),
 *   GetGridVoxelSize(i) and GetGridBoundingBox(i) describe every grid of the file;
 * - value types: float (also files saved as half float), double, int32, bool (as unsigned char
 *   0/1), and Vec3 float/double grids as their magnitude (default) or as three components;
 * - level sets: the signed distance as stored, or a fog volume (LevelSetToFogVolume: 1 inside,
 *   falling to 0 across the narrow band outside, OpenVDB's sdfToFogVolume);
 * - the index-to-world transform: translation to the origin, the lengths of the index axes to
 *   the spacing, their directions to the direction matrix (rotations give an orthonormal one;
 *   general affine maps with shear a non-orthonormal one, with a warning, since volume mappers
 *   need orthonormal directions); non-linear (frustum) transforms are refused with an error;
 * - the extent: the grid's active voxel bounding box (leaf voxels and active tiles), inclusive,
 *   or a user index box (UseBoundingBox, BoundingBox); voxels that are not stored read as the
 *   grid's background value;
 * - a memory guard: boxes larger than MaximumNumberOfVoxels are downsampled by averaging blocks of
 *   f^3 voxels (with a warning); DownsamplingFactor asks for it directly. Downsampled integer and
 *   bool grids come out as float.
 *
 * The copy goes through OpenVDB's multi-threaded tools::copyToDense straight into the VTK array
 * (x fastest, like vtkImageData), slab by slab, with progress events. Errors (missing file, not a
 * VDB file, an empty or truncated file, an unknown grid name, an unsupported value type or
 * transform) give a vtkErrorMacro and an empty output; no exception escapes.
 */
#ifndef vtkOpenVDBImageReader_h
#define vtkOpenVDBImageReader_h

#include "vtkIOOpenVDBImageModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <memory> // for std::unique_ptr

class VTKIOOPENVDBIMAGE_EXPORT vtkOpenVDBImageReader : public vtkImageAlgorithm
{
public:
  static vtkOpenVDBImageReader* New();
  vtkTypeMacro(vtkOpenVDBImageReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The .vdb file.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The grid to read. Default: empty, meaning `density` if present, else the first grid with
   * scalar values, else the first grid.
   */
  vtkSetStringMacro(GridName);
  vtkGetStringMacro(GridName);
  ///@}

  enum VectorModes
  {
    VECTOR_MAGNITUDE = 0,
    VECTOR_COMPONENTS = 1
  };

  ///@{
  /**
   * How vector grids are read: their magnitude (one component, default) or three components.
   */
  vtkSetClampMacro(VectorMode, int, VECTOR_MAGNITUDE, VECTOR_COMPONENTS);
  vtkGetMacro(VectorMode, int);
  ///@}

  ///@{
  /**
   * Convert level sets to fog volumes (OpenVDB's sdfToFogVolume). Default off: the signed
   * distance as stored.
   */
  vtkSetMacro(LevelSetToFogVolume, vtkTypeBool);
  vtkGetMacro(LevelSetToFogVolume, vtkTypeBool);
  vtkBooleanMacro(LevelSetToFogVolume, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Read the inclusive index box BoundingBox (imin, imax, jmin, jmax, kmin, kmax) instead of the
   * grid's active bounding box. Default off.
   */
  vtkSetMacro(UseBoundingBox, vtkTypeBool);
  vtkGetMacro(UseBoundingBox, vtkTypeBool);
  vtkBooleanMacro(UseBoundingBox, vtkTypeBool);
  vtkSetVector6Macro(BoundingBox, int);
  vtkGetVector6Macro(BoundingBox, int);
  ///@}

  ///@{
  /**
   * Largest number of voxels to produce; larger boxes are downsampled by averaging.
   * Default 2^27 (512^3).
   */
  vtkSetClampMacro(MaximumNumberOfVoxels, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfVoxels, vtkIdType);
  ///@}

  ///@{
  /**
   * Average blocks of f^3 voxels into one. Default 1 (none).
   */
  vtkSetClampMacro(DownsamplingFactor, int, 1, 1024);
  vtkGetMacro(DownsamplingFactor, int);
  ///@}

  ///@{
  /**
   * The grids of the file, valid after UpdateInformation (0 / empty when none), in the order
   * OpenVDB lists them (by name).
   */
  int GetNumberOfGrids();
  const char* GetGridName(int index);
  /// "fog volume", "level set", "staggered" or "unknown".
  const char* GetGridClass(int index);
  /// OpenVDB's value type name, e.g. "float", "double", "int32", "bool", "vec3s".
  const char* GetGridValueType(int index);
  /// World size of a voxel along x, y, z.
  void GetGridVoxelSize(int index, double size[3]);
  /// Inclusive index bounding box (imin, imax, jmin, jmax, kmin, kmax) recorded in the file.
  void GetGridBoundingBox(int index, int box[6]);
  ///@}

  /**
   * Whether the file can be read as a VDB file (it opens and has at least one grid).
   */
  static bool CanReadFile(const char* fileName);

protected:
  vtkOpenVDBImageReader();
  ~vtkOpenVDBImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  char* GridName = nullptr;
  int VectorMode = VECTOR_MAGNITUDE;
  vtkTypeBool LevelSetToFogVolume = 0;
  vtkTypeBool UseBoundingBox = 0;
  int BoundingBox[6] = { 0, 0, 0, 0, 0, 0 };
  vtkIdType MaximumNumberOfVoxels = vtkIdType(1) << 27;
  int DownsamplingFactor = 1;

private:
  vtkOpenVDBImageReader(const vtkOpenVDBImageReader&) = delete;
  void operator=(const vtkOpenVDBImageReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
