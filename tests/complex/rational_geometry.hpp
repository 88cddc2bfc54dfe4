#pragma once
// Exact rational geometry for the dual-complex oracles (test only): orthocentres by
// Gaussian elimination, powers computed from coordinates, a brute-force regular
// triangulation for points in general position, and brute-force membership in K by
// enumerating the faces of the dual power face (shares no formula with the code checked).

#include <gmpxx.h>
#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "rstruct/complex/simplicial_complex.hpp"
#include "rstruct/geometry/vec3.hpp"

namespace rstruct::complex::testing {

using Q = mpq_class;
using QVec = std::array<Q, 3>;

struct QPoint {
  QVec c;
  Q w;
};

inline QPoint to_q(const WeightedPoint& p) {
  return {{Q(p.c.x), Q(p.c.y), Q(p.c.z)}, Q(p.w)};
}

inline Q power(const QVec& x, const QPoint& p) {
  Q s = -p.w;
  for (int j = 0; j < 3; ++j) s += (x[j] - p.c[j]) * (x[j] - p.c[j]);
  return s;
}

/// Solves A x = rhs (n × n) by Gaussian elimination; nullopt if singular.
inline std::optional<std::vector<Q>> solve(std::vector<std::vector<Q>> a, std::vector<Q> rhs) {
  const std::size_t n = rhs.size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t piv = col;
    while (piv < n && sgn(a[piv][col]) == 0) ++piv;
    if (piv == n) return std::nullopt;
    std::swap(a[piv], a[col]);
    std::swap(rhs[piv], rhs[col]);
    for (std::size_t r = 0; r < n; ++r) {
      if (r == col || sgn(a[r][col]) == 0) continue;
      const Q f = a[r][col] / a[col][col];
      for (std::size_t k = col; k < n; ++k) a[r][k] -= f * a[col][k];
      rhs[r] -= f * rhs[col];
    }
  }
  std::vector<Q> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = rhs[i] / a[i][i];
  return x;
}

/// The point of aff(c_i) with equal power to every point of s (z_s), or nullopt if the
/// centres are affinely dependent. Unknowns z (3) and multipliers: z = c₀ + Σ λ_i u_i with
/// π_i(z) = π₀(z), written as one linear system in (λ).
inline std::optional<QVec> orthocenter(const std::vector<QPoint>& s) {
  const std::size_t k = s.size() - 1;
  if (k == 0) return s[0].c;
  std::vector<QVec> u(k);
  for (std::size_t i = 0; i < k; ++i) {
    for (int j = 0; j < 3; ++j) u[i][j] = s[i + 1].c[j] - s[0].c[j];
  }
  // π_i(z) − π₀(z) = 0  ⟺  2⟨z − c₀, u_i⟩ = |u_i|² − w_i + w₀.
  std::vector<std::vector<Q>> a(k, std::vector<Q>(k));
  std::vector<Q> rhs(k);
  for (std::size_t i = 0; i < k; ++i) {
    for (std::size_t l = 0; l < k; ++l) {
      Q d = 0;
      for (int j = 0; j < 3; ++j) d += u[i][j] * u[l][j];
      a[i][l] = 2 * d;
    }
    Q n2 = 0;
    for (int j = 0; j < 3; ++j) n2 += u[i][j] * u[i][j];
    rhs[i] = n2 - s[i + 1].w + s[0].w;
  }
  const auto lambda = solve(a, rhs);
  if (!lambda) return std::nullopt;
  QVec z = s[0].c;
  for (std::size_t i = 0; i < k; ++i) {
    for (int j = 0; j < 3; ++j) z[j] += (*lambda)[i] * u[i][j];
  }
  return z;
}

/// Finite cells of the regular triangulation of points in general position: the 4-subsets
/// whose orthosphere has every other point strictly outside in power. Sets `degenerate`
/// if some test is a tie (then the result is not meaningful).
inline std::vector<Tetrahedron> brute_force_regular_cells(const std::vector<QPoint>& pts,
                                                          bool& degenerate) {
  std::vector<Tetrahedron> cells;
  const auto n = static_cast<VertexId>(pts.size());
  for (VertexId a = 0; a < n; ++a)
    for (VertexId b = a + 1; b < n; ++b)
      for (VertexId c = b + 1; c < n; ++c)
        for (VertexId d = c + 1; d < n; ++d) {
          const auto z = orthocenter({pts[a], pts[b], pts[c], pts[d]});
          if (!z) continue;  // coplanar centres
          const Q own = power(*z, pts[a]);
          bool empty = true;
          for (VertexId q = 0; q < n && empty; ++q) {
            if (q == a || q == b || q == c || q == d) continue;
            const int s = sgn(power(*z, pts[q]) - own);
            if (s == 0) degenerate = true;
            if (s <= 0) empty = false;
          }
          if (empty) cells.push_back({a, b, c, d});
        }
  return cells;
}

/// A ball set with its exact copy and its regular triangulation's finite cells.
struct BallSet {
  std::vector<WeightedPoint> points;
  std::vector<QPoint> exact;
  std::vector<Tetrahedron> cells;
};

/// Regular triangulation by brute force; false if the set is degenerate or flat.
inline bool triangulate(BallSet& set) {
  set.exact.clear();
  for (const auto& p : set.points) set.exact.push_back(to_q(p));
  bool degenerate = false;
  set.cells = brute_force_regular_cells(set.exact, degenerate);
  return !degenerate && !set.cells.empty();
}

/// A RapidCheck generator's draw: 5 to 8 balls with centres in [−s, s]³ and radii in
/// [lo, 1000) / 800 · s, for a random s in 1..4: small lo gives sparse dual complexes,
/// large lo many tetrahedra in K. Not triangulated yet.
inline BallSet random_ball_set(int lo) {
  const int n = *rc::gen::inRange(5, 9);
  const double spread = *rc::gen::inRange(1, 5);
  BallSet set;
  for (int i = 0; i < n; ++i) {
    const auto coord = [&] { return *rc::gen::inRange(-1000000, 1000000) * spread / 1e6; };
    const double r = *rc::gen::inRange(lo, 1000) / 800.0 * spread;
    set.points.push_back({{coord(), coord(), coord()}, r * r});
  }
  return set;
}

/// The minimisers of π_σ over V_σ = {x : π_σ(x) ≤ π_q(x) ∀q} are among the points z_{σ ∪ A}
/// (the minimiser of π_σ over the affine hull of a face of V_σ, cut out by a set A of other
/// points with σ ∪ A affinely independent, |A| ≤ 3 − dim σ). Calls visit(π_σ(z)) for every
/// such z that lies in V_σ (checked against every other point) until visit returns true;
/// returns whether it did.
template <class Visit>
bool for_each_dual_face_minimum(const std::vector<QPoint>& pts, const std::vector<VertexId>& sigma,
                                Visit&& visit) {
  std::vector<VertexId> others;
  for (VertexId q = 0; q < pts.size(); ++q) {
    if (std::find(sigma.begin(), sigma.end(), q) == sigma.end()) others.push_back(q);
  }
  const std::size_t max_extra = 4 - sigma.size();
  std::vector<VertexId> chosen;
  const auto search = [&](const auto& self, std::size_t start) -> bool {
    std::vector<QPoint> s;
    for (const VertexId v : sigma) s.push_back(pts[v]);
    for (const VertexId v : chosen) s.push_back(pts[v]);
    if (const auto z = orthocenter(s)) {
      const Q value = power(*z, pts[sigma[0]]);
      bool feasible = true;
      for (const VertexId q : others) {
        if (power(*z, pts[q]) < value) {
          feasible = false;
          break;
        }
      }
      if (feasible && visit(value)) return true;
    }
    if (chosen.size() == max_extra) return false;
    for (std::size_t i = start; i < others.size(); ++i) {
      chosen.push_back(others[i]);
      const bool found = self(self, i + 1);
      chosen.pop_back();
      if (found) return true;
    }
    return false;
  };
  return search(search, 0);
}

/// Brute-force test of σ ∈ K: is the minimum of π_σ over V_σ at most 0?
inline bool brute_force_in_k(const std::vector<QPoint>& pts, const std::vector<VertexId>& sigma) {
  return for_each_dual_face_minimum(pts, sigma, [](const Q& value) { return sgn(value) <= 0; });
}

/// Brute-force α(σ), the minimum of π_σ over V_σ (nullopt if V_σ is empty: σ is not a
/// simplex of the regular triangulation).
inline std::optional<Q> brute_force_alpha(const std::vector<QPoint>& pts,
                                          const std::vector<VertexId>& sigma) {
  std::optional<Q> least;
  for_each_dual_face_minimum(pts, sigma, [&](const Q& value) {
    if (!least || value < *least) least = value;
    return false;
  });
  return least;
}

}  // namespace rstruct::complex::testing
