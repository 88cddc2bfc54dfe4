#pragma once
/// \file
/// Gaussian perturbation of sample points, for robustness experiments. Each point moves by
/// an isotropic 3-D Gaussian N(0, σ² I) (so its expected squared displacement is 3σ²).
/// σ is either absolute (length units) or relative to the local feature size: σ(p) =
/// sigma · lfs(p) (the natural scale of r-sampling noise, as in Dey's noisy-sample
/// models). Certificates always refer to the noiseless points.

#include <cstdint>
#include <vector>

#include "rstruct/geometry/vec3.hpp"
#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

enum class NoiseScale {
  kAbsolute,  ///< σ in length units
  kLfs,       ///< σ(p) = sigma · lfs(p); needs a surface with known lfs
};

/// Adds noise in place, deterministically for `seed`. With NoiseScale::kLfs, lfs is taken
/// from `surface` at each (noiseless) point.
/// \throws InvalidInput if sigma is negative or not finite, or kLfs is asked for a surface
/// with unknown lfs (or no surface).
void add_gaussian_noise(std::vector<Point3>& points, double sigma, NoiseScale scale,
                        const Surface* surface, std::uint64_t seed);

}  // namespace rstruct::sampling
