#pragma once
// An independent exact oracle for the predicates, written separately from them: GMP
// rationals converted from the doubles (exact), generic Gaussian elimination, and the
// geometric meaning of each predicate (circumcentre, orthocentre, powers) rather than the
// predicates' own expansions. Slow and simple on purpose.

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <optional>
#include <vector>

#include "rstruct/geometry/vec3.hpp"

namespace rstruct::oracle {

using Q = mpq_class;
using Matrix = std::vector<std::vector<Q>>;
using QPoint = std::array<Q, 3>;

inline QPoint qp(const Point3& p) { return {Q(p.x), Q(p.y), Q(p.z)}; }
inline Q qdot(const QPoint& a, const QPoint& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline QPoint qsub(const QPoint& a, const QPoint& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline QPoint qcross(const QPoint& a, const QPoint& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Determinant by Gaussian elimination with row swaps.
inline Q determinant(Matrix m) {
  const std::size_t n = m.size();
  Q det = 1;
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t piv = col;
    while (piv < n && m[piv][col] == 0) ++piv;
    if (piv == n) return 0;
    if (piv != col) {
      std::swap(m[piv], m[col]);
      det = -det;
    }
    det *= m[col][col];
    for (std::size_t r = col + 1; r < n; ++r) {
      if (m[r][col] == 0) continue;
      const Q f = m[r][col] / m[col][col];
      for (std::size_t c = col; c < n; ++c) m[r][c] -= f * m[col][c];
    }
  }
  return det;
}

/// Solves A x = b (A square, non-singular) by Cramer's rule.
inline std::vector<Q> solve(const Matrix& a, const std::vector<Q>& b) {
  const Q d = determinant(a);
  std::vector<Q> x(b.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    Matrix ai = a;
    for (std::size_t r = 0; r < b.size(); ++r) ai[r][i] = b[r];
    x[i] = determinant(ai) / d;
  }
  return x;
}

inline int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const QPoint A = qp(a), B = qp(b), C = qp(c), D = qp(d);
  const QPoint u = qsub(B, A), v = qsub(C, A), w = qsub(D, A);
  return sgn(determinant({{u[0], u[1], u[2]}, {v[0], v[1], v[2]}, {w[0], w[1], w[2]}}));
}

/// Orthocentre z and its weight W of four weighted points (|p − z|² − w_p = W for all p).
/// std::nullopt if the centres are coplanar.
inline std::optional<std::pair<QPoint, Q>> orthosphere(const std::array<WeightedPoint, 4>& p) {
  const QPoint a = qp(p[0].c);
  Matrix m;
  std::vector<Q> rhs;
  for (std::size_t i = 1; i < 4; ++i) {
    const QPoint q = qp(p[i].c);
    const QPoint d = qsub(q, a);
    m.push_back({2 * d[0], 2 * d[1], 2 * d[2]});
    rhs.push_back(qdot(q, q) - qdot(a, a) - Q(p[i].w) + Q(p[0].w));
  }
  if (determinant(m) == 0) return std::nullopt;
  const std::vector<Q> z = solve(m, rhs);
  const QPoint zc{z[0], z[1], z[2]};
  const QPoint az = qsub(a, zc);
  return std::make_pair(zc, qdot(az, az) - Q(p[0].w));
}

/// Documented meaning of power_test: sign(−π(e)) · orient3d(a, b, c, d), π(e) the power
/// of e against the orthosphere. 0 if a, b, c, d are coplanar.
inline int power_test(const WeightedPoint& a, const WeightedPoint& b, const WeightedPoint& c,
                      const WeightedPoint& d, const WeightedPoint& e) {
  const int o = orient3d(a.c, b.c, c.c, d.c);
  if (o == 0) return 0;
  const auto s = orthosphere({a, b, c, d});
  const QPoint ez = qsub(qp(e.c), s->first);
  const Q power = qdot(ez, ez) - s->second - Q(e.w);
  return -sgn(power) * o;
}

inline int insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                    const Point3& e) {
  return power_test({a, 0}, {b, 0}, {c, 0}, {d, 0}, {e, 0});
}

/// The perturbed lifted predicate −det[(p, |p|² − w_p − ε^(id+1), 1)] of points given as
/// rows, some of them unperturbed (id = nullopt): sign of the first non-zero coefficient
/// of the polynomial in ε, by increasing power.
inline int perturbed_lifted(const std::vector<QPoint>& pts, const std::vector<Q>& weights,
                            const std::vector<std::optional<std::uint32_t>>& ids) {
  const std::size_t n = pts.size();
  // Columns: the first n − 2 coordinates, the height, 1.
  const std::size_t dim = n - 2;
  Matrix base(n, std::vector<Q>(n));
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t i = 0; i < dim; ++i) base[r][i] = pts[r][i];
    base[r][dim] = qdot(pts[r], pts[r]) - weights[r];
    base[r][dim + 1] = 1;
  }
  const Q value = -determinant(base);
  if (value != 0) return sgn(value);
  std::vector<std::size_t> order;
  for (std::size_t r = 0; r < n; ++r) {
    if (ids[r]) order.push_back(r);
  }
  std::sort(order.begin(), order.end(), [&](auto x, auto y) { return *ids[x] < *ids[y]; });
  for (const std::size_t r : order) {
    // Coefficient of ε^(id_r+1) in −det with height_r lowered by it: +det with the height
    // column replaced by the unit vector e_r.
    Matrix u = base;
    for (std::size_t q = 0; q < n; ++q) u[q][dim] = q == r ? 1 : 0;
    const Q coeff = determinant(u);
    if (coeff != 0) return sgn(coeff);
  }
  return 0;
}

/// Perturbed 3D power test.
inline int power_test_sos(const std::array<WeightedPoint, 5>& p,
                          const std::array<std::uint32_t, 5>& ids) {
  std::vector<QPoint> pts;
  std::vector<Q> w;
  std::vector<std::optional<std::uint32_t>> id;
  for (std::size_t i = 0; i < 5; ++i) {
    pts.push_back(qp(p[i].c));
    w.push_back(Q(p[i].w));
    id.emplace_back(ids[i]);
  }
  return perturbed_lifted(pts, w, id);
}

/// In-plane power test of coplanar e against the orthocircle of a, b, c: sign(−π(e)).
inline int coplanar_power_test(const WeightedPoint& a, const WeightedPoint& b,
                               const WeightedPoint& c, const WeightedPoint& e) {
  const QPoint A = qp(a.c), u = qsub(qp(b.c), A), v = qsub(qp(c.c), A);
  // z = A + α u + β v with |z − p|² − w_p equal for p = a, b, c:
  // 2 (z − A)·(p − A) = |p − A|² − w_p + w_a.
  const Matrix m{{2 * qdot(u, u), 2 * qdot(u, v)}, {2 * qdot(v, u), 2 * qdot(v, v)}};
  const std::vector<Q> rhs{qdot(u, u) - Q(b.w) + Q(a.w), qdot(v, v) - Q(c.w) + Q(a.w)};
  const std::vector<Q> ab = solve(m, rhs);
  QPoint z;
  for (std::size_t i = 0; i < 3; ++i) z[i] = A[i] + ab[0] * u[i] + ab[1] * v[i];
  const QPoint az = qsub(A, z), ez = qsub(qp(e.c), z);
  const Q big_w = qdot(az, az) - Q(a.w);
  return -sgn(qdot(ez, ez) - big_w - Q(e.w));
}

/// Perturbed in-plane power test, by the 3D construction: the fourth point a + n (n the
/// plane normal, unperturbed) makes a positively oriented cell whose orthospheres cut
/// the plane in the perturbed orthocircle.
inline int coplanar_power_test_sos(const std::array<WeightedPoint, 4>& p,
                                   const std::array<std::uint32_t, 4>& ids) {
  const QPoint A = qp(p[0].c);
  const QPoint n = qcross(qsub(qp(p[1].c), A), qsub(qp(p[2].c), A));
  const QPoint d{A[0] + n[0], A[1] + n[1], A[2] + n[2]};
  std::vector<QPoint> pts{A, qp(p[1].c), qp(p[2].c), d, qp(p[3].c)};
  std::vector<Q> w{Q(p[0].w), Q(p[1].w), Q(p[2].w), Q(0), Q(p[3].w)};
  std::vector<std::optional<std::uint32_t>> id{ids[0], ids[1], ids[2], std::nullopt, ids[3]};
  return perturbed_lifted(pts, w, id);  // orient3d(a, b, c, a + n) = |n|² > 0
}

/// Power test of collinear e against the orthosegment of a, b: sign(−π(e)) with
/// π(e) = (1 − λ) w_a + λ w_b − λ (1 − λ) |b − a|² − w_e, e = a + λ (b − a).
inline int collinear_power_test(const WeightedPoint& a, const WeightedPoint& b,
                                const WeightedPoint& e) {
  const QPoint A = qp(a.c), u = qsub(qp(b.c), A);
  const Q lambda = qdot(qsub(qp(e.c), A), u) / qdot(u, u);
  const Q power = (1 - lambda) * Q(a.w) + lambda * Q(b.w) - lambda * (1 - lambda) * qdot(u, u) -
                  Q(e.w);
  return -sgn(power);
}

/// Perturbed collinear test by the 3D construction with two unperturbed extra points
/// a + n1, a + n2 spanning, with b − a, a positively oriented cell.
inline int collinear_power_test_sos(const std::array<WeightedPoint, 3>& p,
                                    const std::array<std::uint32_t, 3>& ids) {
  const QPoint A = qp(p[0].c), u = qsub(qp(p[1].c), A);
  QPoint axis{Q(1), Q(0), Q(0)};
  if (qcross(u, axis) == QPoint{Q(0), Q(0), Q(0)}) axis = {Q(0), Q(1), Q(0)};
  const QPoint n1 = qcross(u, axis), n2 = qcross(u, n1);
  const QPoint d1{A[0] + n1[0], A[1] + n1[1], A[2] + n1[2]};
  const QPoint d2{A[0] + n2[0], A[1] + n2[1], A[2] + n2[2]};
  // orient3d(a, b, a + n1, a + n2) = det[u; n1; n2] = (u × n1)·n2 = |n2|² > 0.
  std::vector<QPoint> pts{A, qp(p[1].c), d1, d2, qp(p[2].c)};
  std::vector<Q> w{Q(p[0].w), Q(p[1].w), Q(0), Q(0), Q(p[2].w)};
  std::vector<std::optional<std::uint32_t>> id{ids[0], ids[1], std::nullopt, std::nullopt,
                                               ids[2]};
  return perturbed_lifted(pts, w, id);
}

inline int compare_power_distance(const Point3& x, const WeightedPoint& p,
                                  const WeightedPoint& q) {
  const QPoint X = qp(x), dp = qsub(X, qp(p.c)), dq = qsub(X, qp(q.c));
  return sgn((qdot(dp, dp) - Q(p.w)) - (qdot(dq, dq) - Q(q.w)));
}

inline int side_of_ball(const Point3& x, const Point3& c, double r) {
  const QPoint d = qsub(qp(x), qp(c));
  return sgn(qdot(d, d) - Q(r) * Q(r));
}

}  // namespace rstruct::oracle
