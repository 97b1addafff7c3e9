#include "ScatteringTable.h"

#include "PhaseFunction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <type_traits>

namespace avs
{

namespace
{
constexpr char Magic[8] = { 'A', 'V', 'S', 'S', 'C', 'A', 'T', '\n' };
constexpr std::uint32_t ThetaMappingQuadratic = 1;
constexpr std::uint32_t TauMappingLog1p = 1;
constexpr int MaximumAxisSize = 4096;
constexpr std::size_t GeneratorFieldSize = 64;

// Splits a continuous node coordinate into a lower node and a fraction.
inline void Split(double c, int n, int& i0, double& f)
{
  if (n <= 1)
  {
    i0 = 0;
    f = 0.0;
    return;
  }
  // NaN takes the first node (std::clamp passes NaN through, and its int cast is undefined).
  c = c > 0.0 ? std::min(c, static_cast<double>(n - 1)) : 0.0;
  i0 = std::min(static_cast<int>(c), n - 2);
  f = c - i0;
}

bool HostIsLittleEndian()
{
  const std::uint16_t probe = 1;
  unsigned char b;
  std::memcpy(&b, &probe, 1);
  return b == 1;
}

// Little-endian writer and reader for the file format.
class Writer
{
public:
  std::vector<unsigned char> Bytes;
  template<typename T>
  void Put(T v)
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (!HostIsLittleEndian())
    {
      std::reverse(b, b + sizeof(T));
    }
    this->Bytes.insert(this->Bytes.end(), b, b + sizeof(T));
  }
  template<typename T>
  void PutArray(const std::vector<T>& v)
  {
    for (const T& x : v)
    {
      this->Put(x);
    }
  }
  void PutRaw(const char* p, std::size_t n) { this->Bytes.insert(this->Bytes.end(), p, p + n); }
};

class Reader
{
public:
  Reader(const std::vector<unsigned char>& b, std::size_t end)
    : Bytes(b)
    , End(end)
  {
  }
  template<typename T>
  bool Get(T& v)
  {
    if (this->Pos + sizeof(T) > this->End)
    {
      return false;
    }
    unsigned char b[sizeof(T)];
    std::memcpy(b, this->Bytes.data() + this->Pos, sizeof(T));
    if (!HostIsLittleEndian())
    {
      std::reverse(b, b + sizeof(T));
    }
    std::memcpy(&v, b, sizeof(T));
    this->Pos += sizeof(T);
    return true;
  }
  template<typename T>
  bool GetArray(std::vector<T>& v, std::size_t n)
  {
    v.resize(n);
    for (auto& x : v)
    {
      if (!this->Get(x))
      {
        return false;
      }
    }
    return true;
  }
  bool GetRaw(char* p, std::size_t n)
  {
    if (this->Pos + n > this->End)
    {
      return false;
    }
    std::memcpy(p, this->Bytes.data() + this->Pos, n);
    this->Pos += n;
    return true;
  }
  std::size_t Position() const { return this->Pos; }

private:
  const std::vector<unsigned char>& Bytes;
  std::size_t End;
  std::size_t Pos = 0;
};

void SetError(std::string* error, const std::string& message)
{
  if (error)
  {
    *error = message;
  }
}
} // namespace

std::uint64_t Fnv1a64(const unsigned char* data, std::size_t size)
{
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i)
  {
    h ^= data[i];
    h *= 0x100000001b3ULL;
  }
  return h;
}

// ---------------------------------------------------------------------------------------------
// Axes

double ScatteringTableAxes::Theta(int i) const
{
  const double u = static_cast<double>(i) / (this->NumberOfTheta - 1);
  return Pi * u * u;
}

double ScatteringTableAxes::Tau(int j) const
{
  const double v = static_cast<double>(j) / (this->NumberOfTau - 1);
  return std::expm1(v * std::log1p(this->TauMaximum));
}

double ScatteringTableAxes::Anisotropy(int k) const
{
  if (this->NumberOfAnisotropy == 1)
  {
    return this->AnisotropyMinimum;
  }
  const double w = static_cast<double>(k) / (this->NumberOfAnisotropy - 1);
  return this->AnisotropyMinimum + w * (this->AnisotropyMaximum - this->AnisotropyMinimum);
}

double ScatteringTableAxes::Albedo(int l) const
{
  return this->NumberOfAlbedo == 1 ? 1.0 : static_cast<double>(l) / (this->NumberOfAlbedo - 1);
}

double ScatteringTableAxes::ThetaCoordinate(double theta) const
{
  const double t = std::clamp(theta, 0.0, Pi);
  return std::sqrt(t / Pi) * (this->NumberOfTheta - 1);
}

double ScatteringTableAxes::TauCoordinate(double tau) const
{
  const double t = std::clamp(tau, 0.0, this->TauMaximum);
  return std::log1p(t) / std::log1p(this->TauMaximum) * (this->NumberOfTau - 1);
}

double ScatteringTableAxes::AnisotropyCoordinate(double g) const
{
  if (this->NumberOfAnisotropy == 1)
  {
    return 0.0;
  }
  const double w =
    (g - this->AnisotropyMinimum) / (this->AnisotropyMaximum - this->AnisotropyMinimum);
  return std::clamp(w, 0.0, 1.0) * (this->NumberOfAnisotropy - 1);
}

double ScatteringTableAxes::AlbedoCoordinate(double albedo) const
{
  return std::clamp(albedo, 0.0, 1.0) * (this->NumberOfAlbedo - 1);
}

std::string ScatteringTableAxes::Validate() const
{
  std::ostringstream os;
  if (this->NumberOfTheta < 2 || this->NumberOfTheta > MaximumAxisSize)
  {
    os << "theta axis size " << this->NumberOfTheta << " outside [2, " << MaximumAxisSize << "]";
  }
  else if (this->NumberOfTau < 2 || this->NumberOfTau > MaximumAxisSize)
  {
    os << "tau axis size " << this->NumberOfTau << " outside [2, " << MaximumAxisSize << "]";
  }
  else if (this->NumberOfAnisotropy < 1 || this->NumberOfAnisotropy > MaximumAxisSize)
  {
    os << "anisotropy axis size " << this->NumberOfAnisotropy << " outside [1, " << MaximumAxisSize
       << "]";
  }
  else if (this->NumberOfAlbedo < 2 || this->NumberOfAlbedo > MaximumAxisSize)
  {
    os << "albedo axis size " << this->NumberOfAlbedo << " outside [2, " << MaximumAxisSize << "]";
  }
  else if (!(this->TauMaximum > 0.0 && this->TauMaximum < 1e6))
  {
    os << "maximum optical radius " << this->TauMaximum << " outside (0, 1e6)";
  }
  else if (!(this->AnisotropyMinimum >= -MaximumAnisotropy &&
             this->AnisotropyMaximum <= MaximumAnisotropy &&
             this->AnisotropyMinimum <= this->AnisotropyMaximum))
  {
    os << "anisotropy range [" << this->AnisotropyMinimum << ", " << this->AnisotropyMaximum
       << "] not inside [-0.95, 0.95]";
  }
  return os.str();
}

bool ScatteringTableAxes::operator==(const ScatteringTableAxes& o) const
{
  return this->NumberOfTheta == o.NumberOfTheta && this->NumberOfTau == o.NumberOfTau &&
    this->NumberOfAnisotropy == o.NumberOfAnisotropy && this->NumberOfAlbedo == o.NumberOfAlbedo &&
    this->TauMaximum == o.TauMaximum && this->AnisotropyMinimum == o.AnisotropyMinimum &&
    this->AnisotropyMaximum == o.AnisotropyMaximum;
}

// ---------------------------------------------------------------------------------------------
// Slice

double ScatteringSlice::InScattering(double theta, double tau) const
{
  int i, j;
  double fi, fj;
  Split(this->Axes.ThetaCoordinate(theta), this->Axes.NumberOfTheta, i, fi);
  Split(this->Axes.TauCoordinate(tau), this->Axes.NumberOfTau, j, fj);
  const int n = this->Axes.NumberOfTheta;
  const double a00 = this->A[static_cast<std::size_t>(j) * n + i];
  const double a10 = this->A[static_cast<std::size_t>(j) * n + i + 1];
  const double a01 = this->A[static_cast<std::size_t>(j + 1) * n + i];
  const double a11 = this->A[static_cast<std::size_t>(j + 1) * n + i + 1];
  return (a00 * (1 - fi) + a10 * fi) * (1 - fj) + (a01 * (1 - fi) + a11 * fi) * fj;
}

double ScatteringSlice::InScatteringCos(double cosTheta, double tau) const
{
  return this->InScattering(std::acos(std::clamp(cosTheta, -1.0, 1.0)), tau);
}

double ScatteringSlice::ForwardTransport(double tau) const
{
  if (!(tau > 0.0))
  {
    return 1.0;
  }
  int j;
  double f;
  Split(this->Axes.TauCoordinate(tau), this->Axes.NumberOfTau, j, f);
  const double logGain = this->LogGain[j] * (1 - f) + this->LogGain[j + 1] * f;
  return std::exp(-2.0 * tau + logGain);
}

// ---------------------------------------------------------------------------------------------
// Table

void ScatteringTable::Allocate(const ScatteringTableAxes& axes)
{
  this->Axes = axes;
  const std::size_t nA = static_cast<std::size_t>(axes.NumberOfTheta) * axes.NumberOfTau *
    axes.NumberOfAnisotropy * axes.NumberOfAlbedo;
  const std::size_t nF =
    static_cast<std::size_t>(axes.NumberOfTau) * axes.NumberOfAnisotropy * axes.NumberOfAlbedo;
  const std::size_t nCells = static_cast<std::size_t>(axes.NumberOfTau) * axes.NumberOfAnisotropy;
  this->A.assign(nA, 0.0f);
  this->AError.assign(nA, 0.0f);
  this->F.assign(nF, 0.0f);
  this->FError.assign(nF, 0.0f);
  this->PathsA.assign(nCells, 0);
  this->PathsF.assign(nCells, 0);
}

double ScatteringTable::InScattering(double theta, double tau, double g, double albedo) const
{
  int i[4];
  double f[4];
  Split(this->Axes.ThetaCoordinate(theta), this->Axes.NumberOfTheta, i[0], f[0]);
  Split(this->Axes.TauCoordinate(tau), this->Axes.NumberOfTau, i[1], f[1]);
  Split(this->Axes.AnisotropyCoordinate(g), this->Axes.NumberOfAnisotropy, i[2], f[2]);
  Split(this->Axes.AlbedoCoordinate(albedo), this->Axes.NumberOfAlbedo, i[3], f[3]);
  double sum = 0.0;
  for (int c = 0; c < 16; ++c)
  {
    double w = 1.0;
    int idx[4];
    for (int a = 0; a < 4; ++a)
    {
      const int bit = (c >> a) & 1;
      w *= bit ? f[a] : 1.0 - f[a];
      idx[a] = i[a] + bit;
    }
    if (w == 0.0)
    {
      continue;
    }
    sum += w * this->A[this->AIndex(idx[0], idx[1], idx[2], idx[3])];
  }
  return sum;
}

double ScatteringTable::ForwardTransport(double tau, double g, double albedo) const
{
  if (!(tau > 0.0))
  {
    return 1.0;
  }
  tau = std::min(tau, this->Axes.TauMaximum);
  int i[3];
  double f[3];
  Split(this->Axes.TauCoordinate(tau), this->Axes.NumberOfTau, i[0], f[0]);
  Split(this->Axes.AnisotropyCoordinate(g), this->Axes.NumberOfAnisotropy, i[1], f[1]);
  Split(this->Axes.AlbedoCoordinate(albedo), this->Axes.NumberOfAlbedo, i[2], f[2]);
  double logGain = 0.0;
  for (int c = 0; c < 8; ++c)
  {
    double w = 1.0;
    int idx[3];
    for (int a = 0; a < 3; ++a)
    {
      const int bit = (c >> a) & 1;
      w *= bit ? f[a] : 1.0 - f[a];
      idx[a] = i[a] + bit;
    }
    if (w == 0.0)
    {
      continue;
    }
    const double value = this->F[this->FIndex(idx[0], idx[1], idx[2])];
    logGain += w * (std::log(value) + 2.0 * this->Axes.Tau(idx[0]));
  }
  return std::exp(-2.0 * tau + logGain);
}

ScatteringSlice ScatteringTable::Slice(double g, double albedo) const
{
  ScatteringSlice s;
  s.Axes = this->Axes;
  s.Anisotropy = ClampAnisotropy(g);
  s.Albedo = std::clamp(albedo, 0.0, 1.0);
  const int nTheta = this->Axes.NumberOfTheta;
  const int nTau = this->Axes.NumberOfTau;
  int k, l;
  double fk, fl;
  Split(this->Axes.AnisotropyCoordinate(s.Anisotropy), this->Axes.NumberOfAnisotropy, k, fk);
  Split(this->Axes.AlbedoCoordinate(s.Albedo), this->Axes.NumberOfAlbedo, l, fl);
  const int k1 = std::min(k + 1, this->Axes.NumberOfAnisotropy - 1);
  const double w[4] = { (1 - fk) * (1 - fl), fk * (1 - fl), (1 - fk) * fl, fk * fl };
  const int kk[4] = { k, k1, k, k1 };
  const int ll[4] = { l, l, l + 1, l + 1 };
  s.A.assign(static_cast<std::size_t>(nTheta) * nTau, 0.0f);
  s.LogGain.assign(nTau, 0.0f);
  for (int j = 0; j < nTau; ++j)
  {
    for (int i = 0; i < nTheta; ++i)
    {
      double a = 0.0;
      for (int c = 0; c < 4; ++c)
      {
        a += w[c] * this->A[this->AIndex(i, j, kk[c], ll[c])];
      }
      s.A[static_cast<std::size_t>(j) * nTheta + i] = static_cast<float>(a);
    }
    double lg = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      lg += w[c] * (std::log(this->F[this->FIndex(j, kk[c], ll[c])]) + 2.0 * this->Axes.Tau(j));
    }
    s.LogGain[j] = static_cast<float>(lg);
  }
  return s;
}

namespace
{
double MaximumRelativeError(const std::vector<float>& value,
  const std::vector<float>& error,
  double threshold)
{
  double peak = 0.0;
  for (float v : value)
  {
    peak = std::max(peak, static_cast<double>(v));
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < value.size(); ++i)
  {
    if (value[i] > 0.0f && value[i] >= threshold * peak)
    {
      worst = std::max(worst, static_cast<double>(error[i]) / value[i]);
    }
  }
  return worst;
}
} // namespace

double ScatteringTable::MaximumRelativeErrorA(double threshold) const
{
  return MaximumRelativeError(this->A, this->AError, threshold);
}

double ScatteringTable::MaximumRelativeErrorF(double threshold) const
{
  return MaximumRelativeError(this->F, this->FError, threshold);
}

// ---------------------------------------------------------------------------------------------
// File format (little-endian):
//   char[8] magic "AVSSCAT\n"; u32 version; u32 header bytes (up to the axes arrays);
//   u32 nTheta, nTau, nG, nAlbedo; u32 theta mapping (1), tau mapping (1);
//   f64 tauMax, gMin, gMax; u64 seed; f64 target relative error; f64 generation seconds;
//   char[64] generator; f64 axes (theta, tau, g, albedo);
//   f32 A, AError (nTheta nTau nG nAlbedo each); f32 F, FError (nTau nG nAlbedo each);
//   u64 pathsA, pathsF (nTau nG each); u64 FNV-1a checksum of all preceding bytes.

std::vector<unsigned char> ScatteringTable::Serialize() const
{
  const auto& ax = this->Axes;
  Writer w;
  w.PutRaw(Magic, sizeof(Magic));
  w.Put<std::uint32_t>(FileVersion);
  const std::uint32_t headerBytes = 8 + 4 * 8 + 8 * 3 + 8 + 8 * 2 + GeneratorFieldSize;
  w.Put<std::uint32_t>(headerBytes);
  w.Put<std::uint32_t>(ax.NumberOfTheta);
  w.Put<std::uint32_t>(ax.NumberOfTau);
  w.Put<std::uint32_t>(ax.NumberOfAnisotropy);
  w.Put<std::uint32_t>(ax.NumberOfAlbedo);
  w.Put<std::uint32_t>(ThetaMappingQuadratic);
  w.Put<std::uint32_t>(TauMappingLog1p);
  w.Put<double>(ax.TauMaximum);
  w.Put<double>(ax.AnisotropyMinimum);
  w.Put<double>(ax.AnisotropyMaximum);
  w.Put<std::uint64_t>(this->Seed);
  w.Put<double>(this->TargetRelativeError);
  w.Put<double>(this->GenerationSeconds);
  char generator[GeneratorFieldSize] = {};
  std::strncpy(generator, this->Generator.c_str(), GeneratorFieldSize - 1);
  w.PutRaw(generator, GeneratorFieldSize);
  for (int i = 0; i < ax.NumberOfTheta; ++i)
  {
    w.Put<double>(ax.Theta(i));
  }
  for (int j = 0; j < ax.NumberOfTau; ++j)
  {
    w.Put<double>(ax.Tau(j));
  }
  for (int k = 0; k < ax.NumberOfAnisotropy; ++k)
  {
    w.Put<double>(ax.Anisotropy(k));
  }
  for (int l = 0; l < ax.NumberOfAlbedo; ++l)
  {
    w.Put<double>(ax.Albedo(l));
  }
  w.PutArray(this->A);
  w.PutArray(this->AError);
  w.PutArray(this->F);
  w.PutArray(this->FError);
  w.PutArray(this->PathsA);
  w.PutArray(this->PathsF);
  const std::uint64_t checksum = Fnv1a64(w.Bytes.data(), w.Bytes.size());
  w.Put<std::uint64_t>(checksum);
  return w.Bytes;
}

bool ScatteringTable::Write(const std::string& fileName, std::string* error) const
{
  // Written beside the target and renamed over it, so that an interrupted write never leaves
  // a truncated table behind.
  const auto bytes = this->Serialize();
  const std::string temporary = fileName + ".part";
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  if (!out)
  {
    SetError(error, "cannot open '" + temporary + "' for writing");
    return false;
  }
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out)
  {
    std::remove(temporary.c_str());
    SetError(error, "error while writing '" + fileName + "'");
    return false;
  }
  if (std::rename(temporary.c_str(), fileName.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    SetError(error, "cannot replace '" + fileName + "'");
    return false;
  }
  return true;
}

bool ScatteringTable::Read(const std::string& fileName, std::string* error)
{
  std::ifstream in(fileName, std::ios::binary);
  if (!in)
  {
    SetError(error, "cannot open scattering table '" + fileName + "'");
    return false;
  }
  std::vector<unsigned char> bytes(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string why;
  if (!this->ReadFromMemory(bytes, &why))
  {
    SetError(error, "scattering table '" + fileName + "': " + why);
    return false;
  }
  return true;
}

bool ScatteringTable::ReadFromMemory(const std::vector<unsigned char>& bytes, std::string* error)
{
  if (bytes.size() < sizeof(Magic) + 8)
  {
    SetError(error, "file too short (" + std::to_string(bytes.size()) + " bytes) to be a table");
    return false;
  }
  if (std::memcmp(bytes.data(), Magic, sizeof(Magic)) != 0)
  {
    SetError(error, "not a scattering table (wrong magic number)");
    return false;
  }
  Reader r(bytes, bytes.size());
  char magic[8];
  r.GetRaw(magic, 8);
  std::uint32_t version = 0, headerBytes = 0;
  r.Get(version);
  r.Get(headerBytes);
  if (version != FileVersion)
  {
    SetError(error,
      "unsupported file version " + std::to_string(version) + " (this build reads version " +
        std::to_string(FileVersion) + ")");
    return false;
  }
  std::uint32_t n[4] = {}, thetaMapping = 0, tauMapping = 0;
  ScatteringTable t;
  double tauMax = 0, gMin = 0, gMax = 0;
  char generator[GeneratorFieldSize + 1] = {};
  const bool headerOk = r.Get(n[0]) && r.Get(n[1]) && r.Get(n[2]) && r.Get(n[3]) &&
    r.Get(thetaMapping) && r.Get(tauMapping) && r.Get(tauMax) && r.Get(gMin) && r.Get(gMax) &&
    r.Get(t.Seed) && r.Get(t.TargetRelativeError) && r.Get(t.GenerationSeconds) &&
    r.GetRaw(generator, GeneratorFieldSize);
  if (!headerOk)
  {
    SetError(error, "truncated header");
    return false;
  }
  if (thetaMapping != ThetaMappingQuadratic || tauMapping != TauMappingLog1p)
  {
    SetError(error, "unknown axis mapping");
    return false;
  }
  ScatteringTableAxes ax;
  ax.NumberOfTheta = static_cast<int>(std::min<std::uint32_t>(n[0], 1u << 30));
  ax.NumberOfTau = static_cast<int>(std::min<std::uint32_t>(n[1], 1u << 30));
  ax.NumberOfAnisotropy = static_cast<int>(std::min<std::uint32_t>(n[2], 1u << 30));
  ax.NumberOfAlbedo = static_cast<int>(std::min<std::uint32_t>(n[3], 1u << 30));
  ax.TauMaximum = tauMax;
  ax.AnisotropyMinimum = gMin;
  ax.AnisotropyMaximum = gMax;
  const std::string axesProblem = ax.Validate();
  if (!axesProblem.empty())
  {
    SetError(error, "bad header: " + axesProblem);
    return false;
  }
  const std::size_t nA = static_cast<std::size_t>(ax.NumberOfTheta) * ax.NumberOfTau *
    ax.NumberOfAnisotropy * ax.NumberOfAlbedo;
  const std::size_t nF =
    static_cast<std::size_t>(ax.NumberOfTau) * ax.NumberOfAnisotropy * ax.NumberOfAlbedo;
  const std::size_t nCells = static_cast<std::size_t>(ax.NumberOfTau) * ax.NumberOfAnisotropy;
  const std::size_t nAxes = static_cast<std::size_t>(ax.NumberOfTheta) + ax.NumberOfTau +
    ax.NumberOfAnisotropy + ax.NumberOfAlbedo;
  const std::size_t expected =
    r.Position() + 8 * nAxes + 4 * (2 * nA + 2 * nF) + 8 * (2 * nCells) + 8;
  if (bytes.size() != expected)
  {
    SetError(error,
      "size mismatch: " + std::to_string(bytes.size()) + " bytes, the header implies " +
        std::to_string(expected) + (bytes.size() < expected ? " (truncated file)" : ""));
    return false;
  }
  const std::uint64_t computed = Fnv1a64(bytes.data(), bytes.size() - 8);
  std::uint64_t stored = 0;
  for (int b = 7; b >= 0; --b)
  {
    stored = (stored << 8) | bytes[bytes.size() - 8 + b];
  }
  if (computed != stored)
  {
    SetError(error, "checksum mismatch (corrupted file)");
    return false;
  }
  std::vector<double> axisValues;
  r.GetArray(axisValues, nAxes);
  std::size_t p = 0;
  auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * (1.0 + std::abs(b)); };
  for (int i = 0; i < ax.NumberOfTheta; ++i)
  {
    if (!near(axisValues[p++], ax.Theta(i)))
    {
      SetError(error, "theta axis does not match its mapping");
      return false;
    }
  }
  for (int j = 0; j < ax.NumberOfTau; ++j)
  {
    if (!near(axisValues[p++], ax.Tau(j)))
    {
      SetError(error, "tau axis does not match its mapping");
      return false;
    }
  }
  for (int k = 0; k < ax.NumberOfAnisotropy; ++k)
  {
    if (!near(axisValues[p++], ax.Anisotropy(k)))
    {
      SetError(error, "anisotropy axis does not match its mapping");
      return false;
    }
  }
  for (int l = 0; l < ax.NumberOfAlbedo; ++l)
  {
    if (!near(axisValues[p++], ax.Albedo(l)))
    {
      SetError(error, "albedo axis does not match its mapping");
      return false;
    }
  }
  t.Axes = ax;
  r.GetArray(t.A, nA);
  r.GetArray(t.AError, nA);
  r.GetArray(t.F, nF);
  r.GetArray(t.FError, nF);
  r.GetArray(t.PathsA, nCells);
  r.GetArray(t.PathsF, nCells);
  for (std::size_t i = 0; i < nA; ++i)
  {
    if (!std::isfinite(t.A[i]) || t.A[i] < 0.0f || !std::isfinite(t.AError[i]))
    {
      SetError(error, "invalid in-scattering value at entry " + std::to_string(i));
      return false;
    }
  }
  for (std::size_t i = 0; i < nF; ++i)
  {
    if (!std::isfinite(t.F[i]) || !(t.F[i] > 0.0f) || !std::isfinite(t.FError[i]))
    {
      SetError(error, "invalid forward transport value at entry " + std::to_string(i));
      return false;
    }
  }
  t.Generator = generator;
  *this = std::move(t);
  return true;
}

} // namespace avs
