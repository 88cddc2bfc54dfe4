#include "rstruct/sampling/random.hpp"

#include <cmath>

namespace rstruct::sampling {

std::uint64_t Random::below(std::uint64_t n) {
  // Accept only draws below the largest multiple of n, so every residue is equally likely.
  const std::uint64_t limit = n * (UINT64_MAX / n);
  for (;;) {
    const std::uint64_t x = engine_();
    if (x < limit) return x % n;
  }
}

double Random::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  for (;;) {
    const double u = 2.0 * uniform01() - 1.0;
    const double v = 2.0 * uniform01() - 1.0;
    const double s = u * u + v * v;
    if (s > 0.0 && s < 1.0) {
      const double m = std::sqrt(-2.0 * std::log(s) / s);
      spare_ = v * m;
      has_spare_ = true;
      return u * m;
    }
  }
}

Vec3 Random::unit_vector() {
  for (;;) {
    const Vec3 g = normal3();
    const double n = norm(g);
    if (n > 1e-3) return g / n;  // reject the (probability ~1e-9) near-zero draws
  }
}

std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace rstruct::sampling
