#pragma once
/// \file
/// A seeded random source whose output is the same on every platform: the engine is
/// std::mt19937_64 (its sequence is fixed by the C++ standard) and the conversions to
/// uniform doubles and Gaussians are written here rather than taken from
/// std::uniform_real_distribution / std::normal_distribution, whose algorithms are
/// implementation-defined.

#include <cstdint>
#include <random>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::sampling {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  /// Raw 64 random bits.
  std::uint64_t bits() { return engine_(); }
  /// Uniform double in [0, 1) with 53 random bits.
  double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform double in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  /// Uniform integer in [0, n), n > 0 (rejection sampling: no modulo bias).
  std::uint64_t below(std::uint64_t n);
  /// Standard normal variate (Marsaglia's polar method).
  double normal();
  /// Vector of three independent standard normal variates.
  Vec3 normal3() {
    const double x = normal();
    const double y = normal();
    return {x, y, normal()};
  }
  /// Uniformly distributed unit vector (normalised Gaussian vector).
  Vec3 unit_vector();

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool has_spare_ = false;
};

/// A seed derived from `seed` and a stream number, so that independent parts of one run
/// (rotation, sample, noise) draw from unrelated streams (SplitMix64 finaliser).
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream);

}  // namespace rstruct::sampling
