// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file vtkMedialRandom.h
 * @brief Counter-based random streams: one independent stream per sample.
 *
 * Each sample i draws from a stream seeded by (seed, i) through SplitMix64, so
 * a sample's random numbers do not depend on which thread runs it or in which
 * order. That is what makes the filters' output identical for any thread count.
 * Internal header; not installed.
 */
#ifndef vtkMedialRandom_h
#define vtkMedialRandom_h

#include <cstdint>

class vtkMedialSampleRandom
{
public:
  vtkMedialSampleRandom(std::uint64_t seed, std::uint64_t sampleIndex)
  {
    // Two mixing rounds decorrelate neighbouring (seed, index) pairs.
    this->State = Mix(seed ^ 0x9E3779B97F4A7C15ull) ^ Mix(sampleIndex + 0xD1B54A32D192ED03ull);
  }

  /// Uniform double in [0, 1), 53 random bits.
  double Uniform() { return static_cast<double>(this->Next() >> 11) * 0x1.0p-53; }

  std::uint64_t Next()
  {
    this->State += 0x9E3779B97F4A7C15ull;
    return Mix(this->State);
  }

private:
  static std::uint64_t Mix(std::uint64_t z)
  {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t State;
};

#endif
