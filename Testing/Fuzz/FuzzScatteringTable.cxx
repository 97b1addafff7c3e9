// Fuzz target: the scattering-table loader (avs::ScatteringTable::ReadFromMemory, which
// vtkAmbientScatteringTable::Load and every renderer use) and the lookups on what it accepts.
//
// Input: one mode byte, then the file. Mode bit 0 recomputes the file's checksum first, so that
// the fuzzer gets past it to the header and value checks. A table that loads must give finite,
// non-negative lookups anywhere (arguments are clamped, NaN takes the first node) and survive a
// write and read back.
#include "FuzzInput.h"
#include "ScatteringTable.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const std::uint8_t mode = data[0];
  std::vector<unsigned char> bytes(data + 1, data + size);
  if ((mode & 1) && bytes.size() >= 16)
  {
    std::uint64_t sum = avs::Fnv1a64(bytes.data(), bytes.size() - 8);
    for (int b = 0; b < 8; ++b)
    {
      bytes[bytes.size() - 8 + b] = static_cast<unsigned char>(sum >> (8 * b));
    }
  }
  avs::ScatteringTable table;
  std::string error;
  const bool ok = table.ReadFromMemory(bytes, &error);
  FUZZ_CHECK(ok || !error.empty());
  if (!ok)
  {
    FUZZ_CHECK(table.A.empty()); // unchanged on failure
    return 0;
  }
  FUZZ_CHECK(table.Axes.Validate().empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  FuzzInput in(data, size);
  const double probes[] = { 0.0, 0.5, 1.0, -1.0, 3.2, 40.0, 1e300, -inf, inf, nan };
  for (int i = 0; i < 24; ++i)
  {
    const double theta = i < 10 ? probes[i] : in.Fraction(-1.0, 4.0);
    const double tau = i < 10 ? probes[(i + 3) % 10] : in.Fraction(-1.0, 40.0);
    const double g = i < 10 ? probes[(i + 5) % 10] : in.Fraction(-1.0, 1.0);
    const double albedo = i < 10 ? probes[(i + 7) % 10] : in.Fraction(-0.1, 1.1);
    const double a = table.InScattering(theta, tau, g, albedo);
    const double f = table.ForwardTransport(tau, g, albedo);
    FUZZ_CHECK(std::isfinite(a) && a >= 0.0);
    FUZZ_CHECK(std::isfinite(f) && f >= 0.0);
    const avs::ScatteringSlice slice = table.Slice(g, albedo);
    FUZZ_CHECK(slice.A.size() ==
      static_cast<std::size_t>(table.Axes.NumberOfTheta) * table.Axes.NumberOfTau);
    const double sa = slice.InScattering(theta, tau);
    const double sf = slice.ForwardTransport(tau);
    FUZZ_CHECK(std::isfinite(sa) && sa >= 0.0);
    FUZZ_CHECK(std::isfinite(sf) && sf >= 0.0);
    FUZZ_CHECK(std::isfinite(slice.InScatteringCos(std::cos(theta), tau)));
  }
  table.MaximumRelativeErrorA();
  table.MaximumRelativeErrorF();
  // What loads writes and loads back to the same table.
  avs::ScatteringTable again;
  FUZZ_CHECK(again.ReadFromMemory(table.Serialize(), &error));
  FUZZ_CHECK(again.Axes == table.Axes && again.A == table.A && again.F == table.F);
  return 0;
}
