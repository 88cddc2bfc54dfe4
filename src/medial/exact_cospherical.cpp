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

}  // namespace

bool exactly_coplanar(const std::array<const BoundaryVertex*, 4>& v, std::span<const Ball> balls) {
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

bool maybe_coplanar(const std::array<Point3, 4>& p) {
  const Vec3 a = p[1] - p[0], b = p[2] - p[0], c = p[3] - p[0];
  const double value = dot(a, cross(b, c));
  const Vec3 aa{std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)};
  const Vec3 ba{std::fabs(b.x), std::fabs(b.y), std::fabs(b.z)};
  const Vec3 ca{std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)};
  const Vec3 bc{ba.y * ca.z + ba.z * ca.y, ba.z * ca.x + ba.x * ca.z, ba.x * ca.y + ba.y * ca.x};
  return std::fabs(value) <= 1e-8 * dot(aa, bc);
}

}  // namespace rstruct::medial
