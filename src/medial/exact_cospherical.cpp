#include "medial/exact_cospherical.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "medial/sphere_incidence.hpp"

namespace rstruct::medial {
namespace {
/// An element of Q(√R₀, …, √R_{k−1}): Σ c_m ∏_{i ∈ m} √R_i over bit masks m, the
/// radicands given to each product.
class Radical {
 public:
  Radical() = default;
  explicit Radical(const mpq_class& c) {
    if (sgn(c) != 0) t_.push_back({0u, c});
  }
  static Radical mono(std::uint32_t m, const mpq_class& c) {
    Radical r;
    if (sgn(c) != 0) r.t_.push_back({m, c});
    return r;
  }
  friend Radical operator+(const Radical& a, const Radical& b) { return a.comb(b, 1); }
  friend Radical operator-(const Radical& a, const Radical& b) { return a.comb(b, -1); }
  Radical times(const Radical& b, const std::vector<mpq_class>& R) const {
    Radical r;
    for (const auto& [ma, ca] : t_)
      for (const auto& [mb, cb] : b.t_) {
        mpq_class c = ca * cb;
        const std::uint32_t both = ma & mb;
        for (std::size_t i = 0; i < R.size(); ++i)
          if (both & (1u << i)) c *= R[i];
        r.t_.push_back({ma ^ mb, c});
      }
    r.norm();
    return r;
  }
  bool zero() const { return t_.empty(); }

 private:
  struct T {
    std::uint32_t m;
    mpq_class c;
  };
  Radical comb(const Radical& b, int s) const {
    Radical r = *this;
    for (const auto& [m, c] : b.t_) r.t_.push_back({m, s > 0 ? c : mpq_class(-c)});
    r.norm();
    return r;
  }
  void norm() {
    std::sort(t_.begin(), t_.end(), [](const T& x, const T& y) { return x.m < y.m; });
    std::vector<T> o;
    for (auto& t : t_) {
      if (!o.empty() && o.back().m == t.m)
        o.back().c += t.c;
      else
        o.push_back(std::move(t));
    }
    o.erase(std::remove_if(o.begin(), o.end(), [](const T& t) { return sgn(t.c) == 0; }), o.end());
    t_ = std::move(o);
  }
  std::vector<T> t_;
};
/// √x, if x ≥ 0 is the square of a rational.
bool rsqrt(const mpq_class& x, mpq_class& root) {
  if (sgn(x) < 0) return false;
  if (!mpz_perfect_square_p(x.get_num_mpz_t()) || !mpz_perfect_square_p(x.get_den_mpz_t()))
    return false;
  mpz_class a, b;
  mpz_sqrt(a.get_mpz_t(), x.get_num_mpz_t());
  mpz_sqrt(b.get_mpz_t(), x.get_den_mpz_t());
  root = mpq_class(a, b);
  root.canonicalize();
  return true;
}
/// N exact points in one field Q(√R₀, …): one radicand per point with h > 0, then each
/// radicand that some product with earlier kept ones makes a rational square is replaced
/// by a monomial in those (√R_j = q / ∏_S R_i · ∏_S √R_i), so the kept roots' monomials
/// are linearly independent over Q.
template <std::size_t N>
struct Field {
  std::array<ExactVertex, N> e;
  std::vector<mpq_class> KR;
  std::array<Radical, N> root;
  Field(const std::array<const BoundaryVertex*, N>& v, std::span<const Ball> balls) {
    for (std::size_t i = 0; i < N; ++i) e[i] = exact_vertex(*v[i], balls);
    std::vector<mpq_class> R;
    std::array<int, N> var{};
    for (std::size_t i = 0; i < N; ++i) {
      var[i] = -1;
      if (sgn(e[i].h) > 0) {
        var[i] = (int)R.size();
        R.push_back(e[i].h);
      }
    }
    const int k = (int)R.size();
    std::vector<std::uint32_t> smask(k);
    std::vector<mpq_class> sfac(k, mpq_class(1));
    std::vector<bool> kept(k, true);
    for (int j = 0; j < k; ++j) smask[j] = 1u << j;
    for (int j = 0; j < k; ++j) {
      std::vector<int> before;
      for (int i = 0; i < j; ++i)
        if (kept[i]) before.push_back(i);
      for (std::uint32_t s = 0; s < (1u << before.size()); ++s) {
        mpq_class prod = R[j];
        std::uint32_t mask = 0;
        for (std::size_t b = 0; b < before.size(); ++b)
          if (s & (1u << b)) {
            prod *= R[before[b]];
            mask |= 1u << before[b];
          }
        mpq_class qq;
        if (!rsqrt(prod, qq)) continue;
        mpq_class f = qq;
        for (std::size_t b = 0; b < before.size(); ++b)
          if (s & (1u << b)) f /= R[before[b]];
        kept[j] = false;
        smask[j] = mask;
        sfac[j] = f;
        break;
      }
    }
    KR.resize(k);
    for (int j = 0; j < k; ++j) KR[j] = kept[j] ? R[j] : mpq_class(1);
    for (std::size_t i = 0; i < N; ++i)
      root[i] = var[i] < 0 ? Radical() : Radical::mono(smask[var[i]], sfac[var[i]]);
  }
  Radical coord(std::size_t i, int a) const {
    return Radical(e[i].o[a]) + root[i].times(Radical(mpq_class(e[i].side) * e[i].n[a]), KR);
  }
  Radical mul(const Radical& a, const Radical& b) const { return a.times(b, KR); }
};

/// A closed interval with outward rounding: every operation's rounded-to-nearest result
/// is widened by one ulp on each side (IEEE operations and sqrt are correctly rounded, so
/// the exact result lies within one ulp). Used only to prove a determinant non-zero.
struct Interval {
  double lo = 0, hi = 0;
  Interval() = default;
  explicit Interval(double x) : lo(x), hi(x) {}
  Interval(double l, double h) : lo(l), hi(h) {}
  static Interval widen(double l, double h) {
    return {std::nextafter(l, -INFINITY), std::nextafter(h, INFINITY)};
  }
  friend Interval operator+(const Interval& a, const Interval& b) {
    return widen(a.lo + b.lo, a.hi + b.hi);
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return widen(a.lo - b.hi, a.hi - b.lo);
  }
  friend Interval operator*(const Interval& a, const Interval& b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return widen(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
  }
  /// \pre b excludes 0.
  friend Interval operator/(const Interval& a, const Interval& b) {
    const double p[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
    return widen(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
  }
  bool excludes_zero() const { return lo > 0 || hi < 0; }
  bool finite() const { return std::isfinite(lo) && std::isfinite(hi); }
};

Interval widen_sqrt(const Interval& h) {
  return Interval::widen(std::sqrt(std::max(h.lo, 0.0)), std::sqrt(h.hi));
}

using I3 = std::array<Interval, 3>;

Interval idot(const I3& a, const I3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// An enclosure of the exact point of a boundary vertex (the construction of exact_vertex,
/// in intervals); false if it cannot be formed (a denominator or h may contain zero).
bool enclose(const BoundaryVertex& v, std::span<const Ball> balls, I3& out) {
  const Ball& bi = balls[v.balls[0]];
  const Ball& bj = balls[v.balls[1]];
  const Ball& bk = balls[v.balls[2]];
  const I3 ci{Interval(bi.c.x), Interval(bi.c.y), Interval(bi.c.z)};
  const I3 u{Interval(bj.c.x) - ci[0], Interval(bj.c.y) - ci[1], Interval(bj.c.z) - ci[2]};
  const I3 w{Interval(bk.c.x) - ci[0], Interval(bk.c.y) - ci[1], Interval(bk.c.z) - ci[2]};
  const Interval ri2 = Interval(bi.r) * Interval(bi.r), rj2 = Interval(bj.r) * Interval(bj.r),
                 rk2 = Interval(bk.r) * Interval(bk.r);
  const Interval uu = idot(u, u), uw = idot(u, w), ww = idot(w, w), half(0.5);
  const Interval bu = (uu - rj2 + ri2) * half, bw = (ww - rk2 + ri2) * half;
  const Interval det = uu * ww - uw * uw;
  if (!det.excludes_zero()) return false;
  const Interval alpha = (bu * ww - bw * uw) / det, beta = (bw * uu - bu * uw) / det;
  I3 z, n;
  for (int a = 0; a < 3; ++a) z[a] = alpha * u[a] + beta * w[a];
  n = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  const Interval nn = idot(n, n);
  if (!nn.excludes_zero()) return false;
  const Interval h = (ri2 - idot(z, z)) / nn;
  if (!(h.hi >= 0)) return false;
  const Interval root = widen_sqrt(h);
  const Interval side(static_cast<double>(v.side));
  for (int a = 0; a < 3; ++a) out[a] = ci[a] + z[a] + side * root * n[a];
  for (const Interval& x : out) {
    if (!x.finite()) return false;
  }
  return true;
}

}  // namespace

bool exactly_coplanar(const std::array<const BoundaryVertex*, 4>& v, std::span<const Ball> balls) {
  {  // A certified non-zero orientation in interval arithmetic decides without rationals.
    std::array<I3, 4> p;
    bool ok = true;
    for (int i = 0; i < 4 && ok; ++i) ok = enclose(*v[i], balls, p[i]);
    if (ok) {
      I3 r[3];
      for (int i = 0; i < 3; ++i) {
        for (int a = 0; a < 3; ++a) r[i][a] = p[i][a] - p[3][a];
      }
      const Interval d = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                         r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                         r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
      if (d.excludes_zero()) return false;
    }
  }
  const Field<4> f(v, balls);
  std::array<std::array<Radical, 3>, 3> m;
  for (int i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a) m[i][a] = f.coord(i, a) - f.coord(3, a);
  auto mul = [&](const Radical& a, const Radical& b) { return f.mul(a, b); };
  const Radical d = mul(m[0][0], mul(m[1][1], m[2][2]) - mul(m[1][2], m[2][1])) -
                    mul(m[0][1], mul(m[1][0], m[2][2]) - mul(m[1][2], m[2][0])) +
                    mul(m[0][2], mul(m[1][0], m[2][1]) - mul(m[1][1], m[2][0]));
  return d.zero();
}

bool exactly_cospherical(const std::array<const BoundaryVertex*, 5>& v,
                         std::span<const Ball> balls) {
  {  // A certified non-zero lifted determinant in interval arithmetic decides without
     // rationals (24 terms of the 4 × 4 determinant relative to the fifth point).
    std::array<I3, 5> p;
    bool ok = true;
    for (int i = 0; i < 5 && ok; ++i) ok = enclose(*v[i], balls, p[i]);
    if (ok) {
      Interval m[4][4];
      for (int i = 0; i < 4; ++i) {
        I3 d;
        for (int a = 0; a < 3; ++a) d[a] = p[i][a] - p[4][a];
        m[i][0] = d[0];
        m[i][1] = d[1];
        m[i][2] = d[2];
        m[i][3] = idot(d, d);
      }
      Interval det(0.0);
      std::array<int, 4> perm{0, 1, 2, 3};
      do {
        int inversions = 0;
        for (int i = 0; i < 4; ++i) {
          for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j] ? 1 : 0;
        }
        const Interval t = m[0][perm[0]] * m[1][perm[1]] * m[2][perm[2]] * m[3][perm[3]];
        det = inversions % 2 == 0 ? det + t : det - t;
      } while (std::next_permutation(perm.begin(), perm.end()));
      if (det.excludes_zero()) return false;
    }
  }
  const Field<5> f(v, balls);
  auto mul = [&](const Radical& a, const Radical& b) { return f.mul(a, b); };
  std::array<std::array<Radical, 4>, 4> m;
  for (int i = 0; i < 4; ++i) {
    Radical lift;
    for (int a = 0; a < 3; ++a) {
      m[i][a] = f.coord(i, a) - f.coord(4, a);
      lift = lift + mul(m[i][a], m[i][a]);
    }
    m[i][3] = lift;
  }
  auto det3 = [&](int r0, int r1, int r2) {
    return mul(m[r0][0], mul(m[r1][1], m[r2][2]) - mul(m[r1][2], m[r2][1])) -
           mul(m[r0][1], mul(m[r1][0], m[r2][2]) - mul(m[r1][2], m[r2][0])) +
           mul(m[r0][2], mul(m[r1][0], m[r2][1]) - mul(m[r1][1], m[r2][0]));
  };
  Radical det;
  for (int i = 0; i < 4; ++i) {
    std::array<int, 3> rows{};
    int r = 0;
    for (int q2 = 0; q2 < 4; ++q2)
      if (q2 != i) rows[r++] = q2;
    const Radical mn = mul(det3(rows[0], rows[1], rows[2]), m[i][3]);
    det = (i % 2 == 0) ? det - mn : det + mn;
  }
  return det.zero();
}
bool maybe_cospherical(const std::array<Point3, 5>& p) {
  double m[4][4];
  for (int i = 0; i < 4; ++i) {
    const Vec3 d = p[i] - p[4];
    m[i][0] = d.x;
    m[i][1] = d.y;
    m[i][2] = d.z;
    m[i][3] = dot(d, d);
  }
  // The 24 terms of the 4 × 4 determinant, by permutation parity.
  double value = 0, bound = 0;
  std::array<int, 4> perm{0, 1, 2, 3};
  do {
    int inversions = 0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j] ? 1 : 0;
    }
    const double t = m[0][perm[0]] * m[1][perm[1]] * m[2][perm[2]] * m[3][perm[3]];
    value += inversions % 2 == 0 ? t : -t;
    bound += std::fabs(t);
  } while (std::next_permutation(perm.begin(), perm.end()));
  return std::fabs(value) <= 1e-8 * bound;
}

}  // namespace rstruct::medial
