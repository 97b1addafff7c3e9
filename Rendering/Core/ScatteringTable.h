// The preintegrated scattering table (ALGORITHM.md section 4): the in-scattering table
// A(theta; tau, g, albedo) and the forward transport factor F(tau, g, albedo), with their
// Monte-Carlo standard errors, the versioned binary file that holds them, and interpolation.
//
// Axes (fixed mappings, so that lookups are O(1) and the GPU can use the same coordinates):
//   theta_i = pi * (i / (nTheta - 1))^2          denser near theta = 0 for large g
//   tau_j   = expm1(j / (nTau - 1) * log1p(tauMax))   uniform in log(1 + tau), tau_0 = 0
//   g_k     uniform on [gMin, gMax];   albedo_l uniform on [0, 1]
//
// A is interpolated linearly in the mapped coordinates. F is interpolated as
// F = exp(-2 tau) * Q with log Q linear in the mapped coordinates (Q >= 1 is the gain of the
// scattered light over the direct beam), so F(0) = 1 and F(tau, g, 0) = exp(-2 tau) hold exactly.
#ifndef avs_ScatteringTable_h
#define avs_ScatteringTable_h

#include <cstdint>
#include <string>
#include <vector>

namespace avs
{

struct ScatteringTableAxes
{
  int NumberOfTheta = 64;
  int NumberOfTau = 32;
  int NumberOfAnisotropy = 20;
  int NumberOfAlbedo = 8;
  double TauMaximum = 32.0;
  double AnisotropyMinimum = -0.95;
  double AnisotropyMaximum = 0.95;

  double Theta(int i) const;
  double Tau(int j) const;
  double Anisotropy(int k) const;
  double Albedo(int l) const;

  /// Continuous node coordinate of a value, clamped into [0, n - 1].
  double ThetaCoordinate(double theta) const;
  double TauCoordinate(double tau) const;
  double AnisotropyCoordinate(double g) const;
  double AlbedoCoordinate(double albedo) const;

  /// Empty string when the axes are usable, else what is wrong.
  std::string Validate() const;
  bool operator==(const ScatteringTableAxes& o) const;
};

/// The (theta, tau) slice of A and the tau column of F for one (g, albedo): what the renderers
/// use (the GPU uploads it as a 2D texture). Lookups are bilinear / linear in the mapped
/// coordinates of the axes.
class ScatteringSlice
{
public:
  ScatteringTableAxes Axes;
  double Anisotropy = 0.0;
  double Albedo = 0.0;
  std::vector<float> A;       ///< nTheta x nTau, theta fastest
  std::vector<float> LogGain; ///< nTau: log(F(tau) * exp(2 tau))

  /// A(theta; tau) for the slice's g and albedo. theta in radians, tau = r * averaged sigma_t.
  double InScattering(double theta, double tau) const;
  /// The same from cos(theta).
  double InScatteringCos(double cosTheta, double tau) const;
  /// F(tau) for the slice's g and albedo.
  double ForwardTransport(double tau) const;
};

class ScatteringTable
{
public:
  static constexpr std::uint32_t FileVersion = 1;
  static constexpr const char* GeneratorVersion = "avs-preintegrate 1.0";

  ScatteringTableAxes Axes;
  std::vector<float> A;      ///< nTheta x nTau x nG x nAlbedo, theta fastest
  std::vector<float> AError; ///< Monte-Carlo standard error of A
  std::vector<float> F;      ///< nTau x nG x nAlbedo, tau fastest
  std::vector<float> FError; ///< Monte-Carlo standard error of F
  /// Paths traced per (tau, g) cell for A and for F (0 where the value is analytic).
  std::vector<std::uint64_t> PathsA, PathsF;

  // Provenance written into the header.
  std::uint64_t Seed = 0;
  double TargetRelativeError = 0.0;
  double GenerationSeconds = 0.0;
  std::string Generator = GeneratorVersion;

  /// Allocates zeroed arrays for the axes.
  void Allocate(const ScatteringTableAxes& axes);

  std::size_t AIndex(int theta, int tau, int g, int albedo) const
  {
    return ((static_cast<std::size_t>(albedo) * this->Axes.NumberOfAnisotropy + g) *
               this->Axes.NumberOfTau +
             tau) *
      this->Axes.NumberOfTheta +
      theta;
  }
  std::size_t FIndex(int tau, int g, int albedo) const
  {
    return (static_cast<std::size_t>(albedo) * this->Axes.NumberOfAnisotropy + g) *
      this->Axes.NumberOfTau +
      tau;
  }
  std::size_t CellIndex(int tau, int g) const
  {
    return static_cast<std::size_t>(g) * this->Axes.NumberOfTau + tau;
  }

  /// A(theta; tau, g, albedo), interpolated. Arguments are clamped into the axes' ranges.
  double InScattering(double theta, double tau, double g, double albedo) const;
  /// F(tau, g, albedo), interpolated as described above.
  double ForwardTransport(double tau, double g, double albedo) const;
  /// The (theta, tau) slice for one g and albedo (interpolated between table nodes).
  ScatteringSlice Slice(double g, double albedo) const;

  /// Writes the versioned binary file. Returns false and sets `error` on failure.
  bool Write(const std::string& fileName, std::string* error = nullptr) const;
  /// Reads and checks a file (magic, version, sizes, checksum, axes, values). On failure returns
  /// false, leaves *this unchanged and says why in `error`.
  bool Read(const std::string& fileName, std::string* error = nullptr);
  /// The same from bytes in memory (used by Read and by the tests).
  bool ReadFromMemory(const std::vector<unsigned char>& bytes, std::string* error = nullptr);
  std::vector<unsigned char> Serialize() const;

  /// Largest relative standard error over the entries whose value is at least `threshold` times
  /// the largest value of A (or of F) in the whole table (ALGORITHM.md section 4).
  double MaximumRelativeErrorA(double threshold = 1e-3) const;
  double MaximumRelativeErrorF(double threshold = 1e-3) const;
};

/// 64-bit FNV-1a checksum (the file's integrity check).
std::uint64_t Fnv1a64(const unsigned char* data, std::size_t size);

} // namespace avs

#endif
