/**
 * @class   vtkAmbientScatteringTable
 * @brief   the preintegrated ambient-scattering table, loaded from its file
 *
 * Holds the in-scattering table A(theta; tau, g, albedo) and the forward transport factor
 * F(tau, g, albedo) of ALGORITHM.md section 4: the scattered radiance leaving a homogeneous ball
 * of optical radius tau lit by a directional light, divided by 2 tau, and the share of the light
 * that crosses the ball. The mappers and vtkVolumeReferenceRenderer read it; users rarely need it
 * directly, except to load their own table (made with `avs-preintegrate`).
 *
 * The file is a versioned binary with a header and a checksum. Load() rejects a missing, short,
 * truncated or corrupted file, a wrong magic number or version, and implausible axes, with a
 * vtkErrorMacro saying which; the previously loaded table (if any) stays in place.
 *
 * The default file is the table shipped with the module: the environment variable
 * AVS_SCATTERING_TABLE overrides it; otherwise it is found beside the library that holds this
 * class, in share/ambientscattering (the build tree and an installed tree, wherever it was moved),
 * else under the install prefix the project was configured with.
 */
#ifndef vtkAmbientScatteringTable_h
#define vtkAmbientScatteringTable_h

#include "vtkObject.h"
#include "vtkRenderingAmbientScatteringModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string

namespace avs
{
class ScatteringTable;
}

class VTKRENDERINGAMBIENTSCATTERING_EXPORT vtkAmbientScatteringTable : public vtkObject
{
public:
  static vtkAmbientScatteringTable* New();
  vtkTypeMacro(vtkAmbientScatteringTable, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The table file. Default: empty, meaning GetDefaultFileName().
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * The shipped table's path (see the class description), or an empty string when none is found.
   */
  static std::string GetDefaultFileName();

  /**
   * Loads the file (FileName, or the default). Returns true on success. On failure reports a
   * vtkErrorMacro and keeps what was loaded before.
   */
  bool Load();

  /**
   * Loads the file if FileName changed since the last successful load. Returns whether a table
   * is loaded afterwards.
   */
  bool Update();

  /**
   * Whether a table is loaded.
   */
  bool IsLoaded() const;

  /**
   * A(theta; tau, g, albedo), theta in radians, interpolated; 0 when no table is loaded.
   */
  double GetInScattering(double theta, double tau, double g, double albedo) const;

  /**
   * F(tau, g, albedo), interpolated; 1 when no table is loaded.
   */
  double GetForwardTransport(double tau, double g, double albedo) const;

  ///@{
  /**
   * Axes and provenance of the loaded table (0 or empty when none is loaded).
   */
  int GetNumberOfTheta() const;
  int GetNumberOfOpticalRadii() const;
  int GetNumberOfAnisotropies() const;
  int GetNumberOfAlbedos() const;
  double GetMaximumOpticalRadius() const;
  const char* GetGenerator() const;
  double GetMaximumRelativeErrorA() const;
  double GetMaximumRelativeErrorF() const;
  ///@}

  /**
   * The loaded table for the module's own classes (nullptr when none is loaded).
   */
  const avs::ScatteringTable* GetTable() const;

protected:
  vtkAmbientScatteringTable();
  ~vtkAmbientScatteringTable() override;

  char* FileName = nullptr;

private:
  vtkAmbientScatteringTable(const vtkAmbientScatteringTable&) = delete;
  void operator=(const vtkAmbientScatteringTable&) = delete;

  std::unique_ptr<avs::ScatteringTable> Table;
  std::string LoadedFileName;
};

#endif
