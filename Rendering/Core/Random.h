// A small, fast, deterministic random number generator (PCG32, O'Neill 2014) for the
// Monte-Carlo code: the same seed and stream give the same numbers on every platform.
#ifndef avs_Random_h
#define avs_Random_h

#include <cstdint>

namespace avs
{

class Random
{
public:
  explicit Random(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0)
  {
    this->State = 0;
    this->Increment = (stream << 1u) | 1u;
    this->NextUInt();
    this->State += seed;
    this->NextUInt();
  }

  std::uint32_t NextUInt()
  {
    const std::uint64_t old = this->State;
    this->State = old * 6364136223846793005ULL + this->Increment;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
  }

  /// Uniform in [0, 1), 53 random bits.
  double Uniform()
  {
    const std::uint64_t hi = this->NextUInt() >> 5;
    const std::uint64_t lo = this->NextUInt() >> 6;
    return static_cast<double>(hi * 67108864ULL + lo) * (1.0 / 9007199254740992.0);
  }

private:
  std::uint64_t State;
  std::uint64_t Increment;
};

/// Mixes integers into one well-spread 64-bit seed (splitmix64 finaliser).
inline std::uint64_t HashSeed(std::uint64_t a, std::uint64_t b = 0, std::uint64_t c = 0)
{
  auto mix = [](std::uint64_t z)
  {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  return mix(a ^ mix(b ^ mix(c)));
}

} // namespace avs

#endif
