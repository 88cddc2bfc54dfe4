#include "rstruct/sampling/noise.hpp"

#include <cmath>
#include <sstream>

#include "rstruct/core/error.hpp"
#include "rstruct/sampling/random.hpp"

namespace rstruct::sampling {

void add_gaussian_noise(std::vector<Point3>& points, double sigma, NoiseScale scale,
                        const Surface* surface, std::uint64_t seed) {
  if (!std::isfinite(sigma) || sigma < 0.0) {
    std::ostringstream msg;
    msg << "noise: sigma must be finite and >= 0, got " << sigma;
    throw InvalidInput(msg.str());
  }
  if (scale == NoiseScale::kLfs && (surface == nullptr || !surface->has_known_lfs())) {
    throw InvalidInput(
        "noise relative to lfs needs a surface with known lfs (sphere, "
        "ellipsoid, torus); use absolute noise");
  }
  if (sigma == 0.0) return;
  Random random(seed);
  for (Point3& p : points) {
    const double s = scale == NoiseScale::kLfs ? sigma * surface->lfs(p) : sigma;
    p += random.normal3() * s;
  }
}

}  // namespace rstruct::sampling
