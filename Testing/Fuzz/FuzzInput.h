// Reads typed values from a fuzzer's bytes; past the end every value is zero, so any input is
// a valid sequence of choices.
#ifndef FuzzInput_h
#define FuzzInput_h

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

class FuzzInput
{
public:
  FuzzInput(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }

  template<typename T>
  T Raw()
  {
    T value{};
    unsigned char bytes[sizeof(T)] = {};
    for (std::size_t i = 0; i < sizeof(T) && this->Position < this->Size; ++i)
    {
      bytes[i] = this->Data[this->Position++];
    }
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }
  std::uint8_t Byte() { return this->Raw<std::uint8_t>(); }
  /// An integer in [lo, hi].
  int Range(int lo, int hi)
  {
    return lo + static_cast<int>(this->Raw<std::uint16_t>() % static_cast<unsigned>(hi - lo + 1));
  }
  /// A number in [lo, hi] on 256 steps.
  double Fraction(double lo, double hi) { return lo + (hi - lo) * this->Byte() / 255.0; }
  const std::uint8_t* Rest() const { return this->Data + this->Position; }
  std::size_t Remaining() const { return this->Size - this->Position; }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

/// The fuzz targets' own checks: a broken invariant aborts, which the fuzzer reports.
#define FUZZ_CHECK(condition)                                                                      \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::fprintf(stderr, "%s:%d: invariant broken: %s\n", __FILE__, __LINE__, #condition);       \
      std::abort();                                                                                \
    }                                                                                              \
  } while (false)

/// Keeps VTK's messages quiet during fuzzing (unless AVS_FUZZ_VERBOSE is set) without turning
/// them off: with the global warning display off, vtkErrorMacro fires no ErrorEvent either.
void FuzzQuietVTK();

#endif
