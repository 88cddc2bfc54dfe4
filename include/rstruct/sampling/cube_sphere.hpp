#pragma once
/// \file
/// The unit sphere parametrized by the six faces of the cube [−1, 1]³ (gnomonic
/// projection): chart f ∈ {0..5} has axis f/2 and sign + for even f; (u, v) ∈ [−1, 1]²
/// maps to w/|w| with w[axis] = ±1, w[axis+1] = u, w[axis+2] = v (indices mod 3).
/// Unlike latitude/longitude it has no poles, so parameter cells stay well shaped.

#include "rstruct/sampling/surface.hpp"

namespace rstruct::sampling {

/// s(u, v) on chart `face` (a unit vector up to rounding).
Vec3 cube_sphere_point(int face, double u, double v);

/// The unnormalised direction w(u, v) (|w|² = 1 + u² + v²).
Vec3 cube_sphere_direction(int face, double u, double v);

/// |s_u × s_v| = (1 + u² + v²)^(−3/2).
double cube_sphere_area_element(double u, double v);

/// Upper bounds of |s_u| and |s_v| over `cell`:
/// |s_u| = sqrt(1 + v²) / (1 + u² + v²) and symmetrically for v; each bounded by taking
/// the largest numerator and smallest denominator over the cell.
struct CubeSphereSpeeds {
  double su = 0;
  double sv = 0;
};
CubeSphereSpeeds cube_sphere_speed_bounds(const ParamCell& cell);

/// Smallest |t| over [lo, hi].
double min_abs_over(double lo, double hi);
/// Largest |t| over [lo, hi].
double max_abs_over(double lo, double hi);

}  // namespace rstruct::sampling
